/* A lit torus through indexed draws: glDrawElements with unsigned byte, short
 * and int indices (GL_TRIANGLES, GL_QUADS: indexed quads split otherwise),
 * glDrawRangeElements, glMultiDrawElements of quad strips, flat and smooth,
 * with and without a colour array. */
#include "array_common.h"

static torus_mesh m;

int main(int argc, char **argv)
{
    static GLubyte tri8[TORUS_NU * TORUS_NV * 6];
    static GLushort tri16[TORUS_NU * TORUS_NV * 6], quad16[TORUS_NU * TORUS_NV * 4];
    static GLuint strip32[TORUS_NU][2 * (TORUS_NV + 1)];
    const GLvoid *strips[TORUS_NU];
    GLsizei counts[TORUS_NU];
    int i, u, v, cell = 0, small_tris = 0;
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    torus_build(&m, 0.45f, 0.18f);
    /* unsigned byte indices reach only the first 256 vertices: part of the torus */
    for (i = 0; i < m.tri_count; i += 3)
        if (m.tri[i] < 256 && m.tri[i + 1] < 256 && m.tri[i + 2] < 256) {
            tri8[small_tris++] = (GLubyte)m.tri[i];
            tri8[small_tris++] = (GLubyte)m.tri[i + 1];
            tri8[small_tris++] = (GLubyte)m.tri[i + 2];
        }
    for (i = 0; i < m.tri_count; i++) tri16[i] = (GLushort)m.tri[i];
    for (i = 0; i < m.quad_count; i++) quad16[i] = (GLushort)m.quad[i];
    for (u = 0; u < TORUS_NU; u++) {
        for (v = 0; v <= TORUS_NV; v++) {
            strip32[u][2 * v] = torus_at(u, v);
            strip32[u][2 * v + 1] = torus_at(u + 1, v);
        }
        strips[u] = strip32[u];
        counts[u] = 2 * (TORUS_NV + 1);
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, m.pos);
    glNormalPointer(GL_FLOAT, 0, m.nrm);
    glColorPointer(4, GL_FLOAT, 0, m.col);
    for (int with_color = 0; with_color < 2; with_color++) {
        if (with_color) {
            glEnableClientState(GL_COLOR_ARRAY);
            glEnable(GL_COLOR_MATERIAL);
        }
        for (int shade = 0; shade < 2; shade++) {
            glShadeModel(shade ? GL_FLAT : GL_SMOOTH);
            array_cell(cell, 25.0f + 17 * cell); cell++;
            glDrawElements(GL_TRIANGLES, small_tris, GL_UNSIGNED_BYTE, tri8);
            array_cell(cell, 25.0f + 17 * cell); cell++;
            if (shade)
                glDrawRangeElements(GL_TRIANGLES, 0, TORUS_VERTS - 1, m.tri_count, GL_UNSIGNED_INT, m.tri);
            else
                glDrawElements(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, tri16);
            array_cell(cell, 25.0f + 17 * cell); cell++;
            glDrawElements(GL_QUADS, m.quad_count, GL_UNSIGNED_SHORT, quad16);
            array_cell(cell, 25.0f + 17 * cell); cell++;
            glMultiDrawElements(GL_QUAD_STRIP, counts, GL_UNSIGNED_INT, strips, TORUS_NU);
        }
    }
    scene_readpixels_check();
    return scene_end();
}
