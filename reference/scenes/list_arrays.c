/* Array draws compiled into display lists (GL 2.1 §5.4: the array contents
 * are captured at compile time): a lit torus through glDrawElements (GL_QUADS,
 * GL_TRIANGLES) and glDrawArrays, with and without a colour array, next to
 * glBegin/glEnd pairs in the same list (they merge into one vertex node as
 * Mesa's save_DrawArrays makes them), glMultiDrawArrays, glDrawRangeElements,
 * glArrayElement between a list's glBegin/glEnd, and a list from a vertex
 * buffer object. Each list is replayed several times after the arrays (and
 * the buffer) were changed or freed: the replays must draw the compiled
 * contents. After a replay an immediate-mode quad is drawn without a colour
 * of its own: it shows which colour the replay left current. */
#include "array_common.h"

static torus_mesh m;
static float pos[TORUS_VERTS][3], nrm[TORUS_VERTS][3], col[TORUS_VERTS][4];
enum { QUADS = 1, TRIS, EXPANDED, MIXED, MULTI, RANGE, ELEMENTS, BUFFER };

static void set_arrays(void)
{
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glNormalPointer(GL_FLOAT, 0, nrm);
    glColorPointer(4, GL_FLOAT, 0, col);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
}

static void scramble(void)
{
    int i;
    for (i = 0; i < TORUS_VERTS; i++) {
        pos[i][0] = -pos[i][0] * 0.5f;
        pos[i][2] += 0.3f;
        nrm[i][1] = -nrm[i][1];
        col[i][0] = 0.1f;
        col[i][1] = 1.0f - col[i][1];
    }
}

static void marker(float x, float y)
{
    /* no colour: takes the current one */
    glDisable(GL_LIGHTING);
    glLoadIdentity();
    glTranslatef(x, y, -10.0f);
    glBegin(GL_QUADS);
    glVertex3f(-0.2f, -0.2f, 0); glVertex3f(0.2f, -0.2f, 0); glVertex3f(0.2f, 0.2f, 0); glVertex3f(-0.2f, 0.2f, 0);
    glEnd();
    glEnable(GL_LIGHTING);
}

int main(int argc, char **argv)
{
    static float flat_pos[TORUS_NU * TORUS_NV * 4][3], flat_nrm[TORUS_NU * TORUS_NV * 4][3],
        flat_col[TORUS_NU * TORUS_NV * 4][4];
    static GLushort tri16[TORUS_NU * TORUS_NV * 6];
    GLint firsts[TORUS_NU];
    GLsizei counts[TORUS_NU];
    GLuint vbo = 0;
    int i, round;
    scene_begin(argc, argv, 200, 200);
    array_lit_setup();
    torus_build(&m, 0.45f, 0.18f);
    memcpy(pos, m.pos, sizeof pos);
    memcpy(nrm, m.nrm, sizeof nrm);
    memcpy(col, m.col, sizeof col);
    for (i = 0; i < m.tri_count; i++) tri16[i] = (GLushort)m.tri[i];
    torus_expand(&m, m.quad, m.quad_count, &flat_pos[0][0], &flat_nrm[0][0], &flat_col[0][0]);
    set_arrays();

    glNewList(QUADS, GL_COMPILE); /* indexed quads, colour array on */
    glEnableClientState(GL_COLOR_ARRAY);
    glEnable(GL_COLOR_MATERIAL);
    glDrawElements(GL_QUADS, m.quad_count, GL_UNSIGNED_INT, m.quad);
    glEndList();
    glNewList(TRIS, GL_COMPILE); /* indexed triangles, no colour array, flat */
    glShadeModel(GL_FLAT);
    glDrawElements(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, tri16);
    glShadeModel(GL_SMOOTH);
    glEndList();
    glDisableClientState(GL_COLOR_ARRAY); /* client state: executed at once */
    glDisable(GL_COLOR_MATERIAL);

    glVertexPointer(3, GL_FLOAT, 0, flat_pos);
    glNormalPointer(GL_FLOAT, 0, flat_nrm);
    glColorPointer(4, GL_FLOAT, 0, flat_col);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnable(GL_COLOR_MATERIAL);
    glNewList(EXPANDED, GL_COMPILE); /* glDrawArrays of quads, in two pieces */
    glDrawArrays(GL_QUADS, 0, m.quad_count / 2);
    glDrawArrays(GL_QUADS, m.quad_count / 2, m.quad_count - m.quad_count / 2);
    glEndList();
    glNewList(MIXED, GL_COMPILE); /* glBegin/glEnd pairs around an array draw */
    glBegin(GL_QUADS);
    for (i = 0; i < 40; i++) {
        glColor4fv(flat_col[i]);
        glNormal3fv(flat_nrm[i]);
        glVertex3fv(flat_pos[i]);
    }
    glEnd();
    glDrawArrays(GL_QUADS, 40, 200);
    glBegin(GL_QUADS);
    for (i = 240; i < 400; i++) glArrayElement(i); /* joins the node */
    glEnd();
    glDrawArrays(GL_TRIANGLE_STRIP, 400, 60);
    glDrawArrays(GL_TRIANGLE_STRIP, 460, 60);
    glEndList();
    for (i = 0; i < TORUS_NU; i++) {
        firsts[i] = i * TORUS_NV * 4;
        counts[i] = i % 3 ? TORUS_NV * 4 : 0;
    }
    glNewList(MULTI, GL_COMPILE);
    glMultiDrawArrays(GL_QUADS, firsts, counts, TORUS_NU);
    glEndList();
    glDisableClientState(GL_COLOR_ARRAY);

    set_arrays();
    glNewList(RANGE, GL_COMPILE);
    glDrawRangeElements(GL_TRIANGLES, 0, TORUS_VERTS - 1, m.tri_count / 2, GL_UNSIGNED_SHORT, tri16);
    glEndList();
    glEnableClientState(GL_COLOR_ARRAY);
    glNewList(ELEMENTS, GL_COMPILE); /* glArrayElement between the list's glBegin/glEnd */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < m.tri_count / 2; i++) glArrayElement((GLint)m.tri[i]);
    glEnd();
    glEndList();
    glDisableClientState(GL_COLOR_ARRAY);

    glGenBuffers(1, &vbo); /* the vertices from a buffer object */
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof pos, pos, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glNewList(BUFFER, GL_COMPILE);
    glDrawElements(GL_QUADS, m.quad_count, GL_UNSIGNED_INT, m.quad);
    glEndList();
    glDeleteBuffers(1, &vbo); /* the list keeps what it read */

    scene_clear();
    glColor3f(0.9f, 0.9f, 0.2f);
    for (round = 0; round < 2; round++) {
        const float a = 20.0f + 35.0f * round;
        array_cell(0 + 8 * round, a); glCallList(QUADS);
        marker(-1.9f + 2.5f * round, -2.4f);
        glDisableClientState(GL_COLOR_ARRAY); glDisable(GL_COLOR_MATERIAL);
        array_cell(1 + 8 * round, a); glCallList(TRIS);
        array_cell(2 + 8 * round, a); glEnable(GL_COLOR_MATERIAL); glCallList(EXPANDED);
        marker(-0.6f + 2.5f * round, -2.4f);
        array_cell(3 + 8 * round, a); glCallList(MIXED);
        marker(0.6f + 2.5f * round, -2.4f);
        array_cell(4 + 8 * round, a); glCallList(MULTI);
        glDisable(GL_COLOR_MATERIAL);
        array_cell(5 + 8 * round, a); glCallList(RANGE);
        array_cell(6 + 8 * round, a); glEnable(GL_COLOR_MATERIAL); glCallList(ELEMENTS);
        marker(1.9f + 2.5f * round, -2.4f);
        glDisable(GL_COLOR_MATERIAL);
        array_cell(7 + 8 * round, a); glCallList(BUFFER);
        scramble(); /* the next round's replays must not see this */
    }
    return scene_end();
}
