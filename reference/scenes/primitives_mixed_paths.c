/* Issue 12's state through every submission path at once: a quad mesh in
 * GL_LINE and GL_POINT polygon modes drawn with glDrawArrays, glDrawElements
 * and a display list (with glPolygonMode, glLineWidth, glPointSize and
 * glLineStipple compiled into it); polygon offset between the passes; an edge
 * flag array; user clip planes and the scissor on top. Lit, two-sided.
 * Colours and coverage are identical; the depth of lines in the draw that
 * the user clip plane cuts is 1 or 2 off in 10 to 20 pixels (not explained
 * yet; the harness reports it in the notes column). */
#include "scene.h"
#include <math.h>

#define N 7
static GLfloat pos[N * N][3], nrm[N * N][3];
static GLboolean flags[N * N];
static GLushort quads[(N - 1) * (N - 1) * 4];

static void build_mesh(void)
{
    int i, j, k = 0;
    for (j = 0; j < N; j++)
        for (i = 0; i < N; i++) {
            float u = (float)i / (N - 1) * 2 - 1, v = (float)j / (N - 1) * 2 - 1;
            float z = 0.3f * sinf(2.0f * u) * cosf(1.5f * v);
            GLfloat *p = pos[j * N + i], *n = nrm[j * N + i];
            p[0] = u; p[1] = v; p[2] = z;
            n[0] = -0.6f * cosf(2.0f * u) * cosf(1.5f * v); n[1] = 0.45f * sinf(2.0f * u) * sinf(1.5f * v); n[2] = 1;
            flags[j * N + i] = (GLboolean)((i + j) % 3 != 0);
        }
    for (j = 0; j < N - 1; j++)
        for (i = 0; i < N - 1; i++) {
            quads[k++] = (GLushort)(j * N + i); quads[k++] = (GLushort)(j * N + i + 1);
            quads[k++] = (GLushort)((j + 1) * N + i + 1); quads[k++] = (GLushort)((j + 1) * N + i);
        }
}

static void lights(void)
{
    const GLfloat p0[4] = {0.5f, 1.0f, 2.0f, 0.0f}, p1[4] = {-2.0f, -1.0f, 1.0f, 1.0f};
    const GLfloat d1[4] = {0.3f, 0.5f, 1.0f, 1.0f}, s[4] = {1, 1, 1, 1};
    const GLfloat front[4] = {0.9f, 0.5f, 0.2f, 1}, back[4] = {0.2f, 0.7f, 0.4f, 1};
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_POSITION, p0);
    glLightfv(GL_LIGHT1, GL_POSITION, p1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
    glLightfv(GL_LIGHT0, GL_SPECULAR, s);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, front);
    glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, back);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
}

static void place(float x, float y, float angle)
{
    glLoadIdentity();
    glTranslatef(x, y, -6.0f);
    glRotatef(angle, 1.0f, 0.4f, 0.0f);
    glScalef(0.9f, 0.9f, 0.9f);
}

int main(int argc, char **argv)
{
    GLuint list;
    const GLdouble plane[4] = {1.0, 0.3, 0.0, 0.55};
    scene_begin(argc, argv, 240, 180);
    build_mesh();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.2, 1.2, -0.9, 0.9, 2.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    lights();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glNormalPointer(GL_FLOAT, 0, nrm);

    /* Top left: hidden-line by arrays: fill pushed back, then GL_LINE on top. */
    place(-1.5f, 1.1f, 35.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glDrawElements(GL_QUADS, (N - 1) * (N - 1) * 4, GL_UNSIGNED_SHORT, quads);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDisable(GL_LIGHTING);
    glColor3f(0.1f, 0.1f, 0.1f);
    glDrawElements(GL_QUADS, (N - 1) * (N - 1) * 4, GL_UNSIGNED_SHORT, quads);
    glEnable(GL_LIGHTING);

    /* Top right: edge flag array, GL_LINE front, GL_POINT back, wide. */
    place(1.5f, 1.1f, 150.0f);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glEdgeFlagPointer(0, flags);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glLineWidth(2.0f);
    glPointSize(3.0f);
    glDrawElements(GL_QUADS, (N - 1) * (N - 1) * 4, GL_UNSIGNED_SHORT, quads);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);

    /* Bottom left: a display list with the state compiled in, called twice,
     * the second time under a user clip plane. */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x3F3F);
    glLineWidth(1.0f);
    glDrawArrays(GL_LINE_STRIP, 0, N * N);
    glDisable(GL_LINE_STIPPLE);
    glPointSize(2.5f);
    glDrawArrays(GL_POINTS, 0, N * N);
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glVertex3f(-0.3f, -0.3f, 0.4f); glVertex3f(0.3f, -0.3f, 0.4f);
    glVertex3f(0.3f, 0.3f, 0.4f); glVertex3f(-0.3f, 0.3f, 0.4f);
    glEnd();
    glEndList();
    place(-1.5f, -1.1f, -30.0f);
    glCallList(list);
    place(-0.2f, -1.1f, 20.0f);
    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    glCallList(list);
    glDisable(GL_CLIP_PLANE0);

    /* Bottom right: scissored, GL_FILL again, smooth shading, glRect. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(150, 10, 80, 70);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    place(1.6f, -1.1f, 60.0f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, N * N);
    glLoadIdentity();
    glTranslatef(0, 0, -6.0f);
    glRectf(1.2f, -2.0f, 2.0f, -1.4f);
    glDisable(GL_SCISSOR_TEST);
    glDeleteLists(list, 1);
    return scene_end();
}
