/* Vertex array objects with base vertex and primitive restart: two lit tori
 * in one array buffer (the second with other colours), each format in its own
 * vertex array object (ARB_vertex_array_object, with its element array
 * buffer), drawn by glDrawElementsBaseVertex (positive and negative base
 * vertex), glDrawRangeElementsBaseVertex, glMultiDrawElementsBaseVertex, and
 * one index list of quad and triangle strips cut by NV_primitive_restart, in
 * smooth and flat shading; then the default object's client arrays again. */
#include "array_common.h"

static torus_mesh m;

#define STRIP_LEN (2 * (TORUS_NV + 1))
#define RESTART 0xFFFFu

int main(int argc, char **argv)
{
    static float pos[2 * TORUS_VERTS][3], nrm[2 * TORUS_VERTS][3];
    static GLubyte col[2 * TORUS_VERTS][4];
    /* tri: the torus's triangles; shifted: the same plus TORUS_VERTS;
     * strips: one quad strip per ring with a restart index between rings */
    static GLushort tri[TORUS_NU * TORUS_NV * 6], shifted[TORUS_NU * TORUS_NV * 6];
    static GLushort strips[TORUS_NU * (STRIP_LEN + 1)];
    GLintptr strips_at;
    GLuint vao[2], buf[2];
    GLsizei counts[2];
    const GLvoid *offsets[2];
    GLint bases[2];
    int i, u, v, n_strip = 0, cell = 0;
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    torus_build(&m, 0.45f, 0.18f);
    for (i = 0; i < 2 * TORUS_VERTS; i++) {
        const int k = i % TORUS_VERTS;
        memcpy(pos[i], m.pos[k], sizeof pos[i]);
        memcpy(nrm[i], m.nrm[k], sizeof nrm[i]);
        for (int c = 0; c < 4; c++) {
            const float f = i < TORUS_VERTS ? m.col[k][c] : (c == 3 ? 1.0f : 1.0f - m.col[k][(c + 1) % 3]);
            col[i][c] = (GLubyte)(f * 255.0f + 0.5f);
        }
    }
    for (i = 0; i < m.tri_count; i++) {
        tri[i] = (GLushort)m.tri[i];
        shifted[i] = (GLushort)(m.tri[i] + TORUS_VERTS);
    }
    for (u = 0; u < TORUS_NU; u++) {
        if (u) strips[n_strip++] = RESTART;
        for (v = 0; v <= TORUS_NV; v++) {
            strips[n_strip++] = (GLushort)torus_at(u, v);
            strips[n_strip++] = (GLushort)torus_at(u + 1, v);
        }
    }
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof pos + sizeof nrm + sizeof col, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof pos, pos);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof pos, sizeof nrm, nrm);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof pos + sizeof nrm, sizeof col, col);
    glGenVertexArrays(2, vao);
    /* vao[0]: positions, normals, colours; the triangle lists in its element buffer */
    glBindVertexArray(vao[0]);
    glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)0);
    glNormalPointer(GL_FLOAT, 0, (const GLvoid *)sizeof pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, (const GLvoid *)(sizeof pos + sizeof nrm));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
    strips_at = sizeof tri + sizeof shifted;
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, strips_at + sizeof strips, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, sizeof tri, tri);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, sizeof tri, sizeof shifted, shifted);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, strips_at, sizeof strips, strips);
    /* vao[1]: positions and normals only (the material's colour); client indices */
    glBindVertexArray(vao[1]);
    glVertexPointer(3, GL_FLOAT, 0, (const GLvoid *)0);
    glNormalPointer(GL_FLOAT, 0, (const GLvoid *)sizeof pos);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glEnable(GL_COLOR_MATERIAL);
    glPrimitiveRestartIndexNV(RESTART);
    for (int shade = 0; shade < 2; shade++) {
        glShadeModel(shade ? GL_FLAT : GL_SMOOTH);
        glBindVertexArray(vao[0]);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        glDrawElementsBaseVertex(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, (const GLvoid *)0, 0);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        glDrawElementsBaseVertex(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, (const GLvoid *)0, TORUS_VERTS);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        /* the shifted list read back onto the first torus, and a range */
        if (shade)
            glDrawRangeElementsBaseVertex(GL_TRIANGLES, TORUS_VERTS, 2 * TORUS_VERTS - 1, m.tri_count,
                                          GL_UNSIGNED_SHORT, (const GLvoid *)sizeof tri, -TORUS_VERTS);
        else
            glDrawElementsBaseVertex(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, (const GLvoid *)sizeof tri,
                                     -TORUS_VERTS);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        /* half of each torus: the first half of the list from each copy */
        counts[0] = counts[1] = m.tri_count / 2;
        offsets[0] = (const GLvoid *)0;
        offsets[1] = (const GLvoid *)(sizeof tri / 2);
        bases[0] = TORUS_VERTS;
        bases[1] = 0;
        glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts, GL_UNSIGNED_SHORT, offsets, 2, bases);
        /* the strips with restart: quad strips, then triangle strips */
        glEnableClientState(GL_PRIMITIVE_RESTART_NV);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        glDrawElements(GL_QUAD_STRIP, n_strip, GL_UNSIGNED_SHORT, (const GLvoid *)strips_at);
        glBindVertexArray(vao[1]);
        glColor4f(0.9f, 0.5f, 0.3f, 1.0f);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        glDrawElementsBaseVertex(GL_TRIANGLE_STRIP, n_strip, GL_UNSIGNED_SHORT, strips, TORUS_VERTS);
        glDisableClientState(GL_PRIMITIVE_RESTART_NV);
        /* the default object: client arrays, as before any object */
        glBindVertexArray(0);
        glVertexPointer(3, GL_FLOAT, 0, pos);
        glNormalPointer(GL_FLOAT, 0, nrm);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        glDrawElementsBaseVertex(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, tri, TORUS_VERTS);
        array_cell(cell, 25.0f + 17 * cell); cell++;
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i < n_strip; i++) {
            if (strips[i] == RESTART)
                glPrimitiveRestartNV();
            else
                glArrayElement(strips[i]);
        }
        glEnd();
    }
    scene_readpixels_check();
    return scene_end();
}
