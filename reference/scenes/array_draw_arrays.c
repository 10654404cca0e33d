/* A lit torus through glDrawArrays: GL_TRIANGLES, GL_QUADS, GL_TRIANGLE_STRIP
 * and GL_QUAD_STRIP rings, with and without a colour array (colour material),
 * flat and smooth, and glMultiDrawArrays of the quad strips. */
#include "array_common.h"

static torus_mesh m;
static float pos[TORUS_NU * TORUS_NV * 6][3], nrm[TORUS_NU * TORUS_NV * 6][3], col[TORUS_NU * TORUS_NV * 6][4];
/* One quad strip per ring around the tube, laid end to end. */
static float spos[TORUS_NU * (TORUS_NV + 1) * 2][3], snrm[TORUS_NU * (TORUS_NV + 1) * 2][3],
    scol[TORUS_NU * (TORUS_NV + 1) * 2][4];

static void set_arrays(float (*p)[3], float (*n)[3], float (*c)[4], int with_color)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, p);
    glNormalPointer(GL_FLOAT, 0, n);
    glColorPointer(4, GL_FLOAT, 0, c);
    if (with_color) {
        glEnableClientState(GL_COLOR_ARRAY);
        glEnable(GL_COLOR_MATERIAL);
    } else {
        glDisableClientState(GL_COLOR_ARRAY);
        glDisable(GL_COLOR_MATERIAL);
    }
}

int main(int argc, char **argv)
{
    int u, v, k = 0, cell = 0;
    GLint first[TORUS_NU];
    GLsizei count[TORUS_NU];
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    torus_build(&m, 0.45f, 0.18f);
    torus_expand(&m, m.tri, m.tri_count, &pos[0][0], &nrm[0][0], &col[0][0]);
    for (u = 0; u < TORUS_NU; u++) {
        first[u] = k;
        count[u] = 2 * (TORUS_NV + 1);
        for (v = 0; v <= TORUS_NV; v++) {
            int a = torus_at(u, v), b = torus_at(u + 1, v);
            memcpy(spos[k], m.pos[a], 12); memcpy(snrm[k], m.nrm[a], 12); memcpy(scol[k], m.col[a], 16); k++;
            memcpy(spos[k], m.pos[b], 12); memcpy(snrm[k], m.nrm[b], 12); memcpy(scol[k], m.col[b], 16); k++;
        }
    }
    for (int shade = 0; shade < 2; shade++) {
        glShadeModel(shade ? GL_FLAT : GL_SMOOTH);
        for (int with_color = 0; with_color < 2; with_color++) {
            array_cell(cell, 30.0f + 20 * cell); cell++;
            set_arrays(pos, nrm, col, with_color);
            glDrawArrays(GL_TRIANGLES, 0, m.tri_count);

            array_cell(cell, 30.0f + 20 * cell); cell++;
            set_arrays(spos, snrm, scol, with_color);
            glMultiDrawArrays(GL_QUAD_STRIP, first, count, TORUS_NU);

            array_cell(cell, 30.0f + 20 * cell); cell++;
            for (u = 0; u < TORUS_NU; u++) glDrawArrays(GL_TRIANGLE_STRIP, first[u], count[u]);
        }
    }
    /* GL_QUADS from plain arrays: every fourth quad strip vertex pair. */
    glShadeModel(GL_SMOOTH);
    {
        static float qpos[TORUS_NU * TORUS_NV * 4][3], qnrm[TORUS_NU * TORUS_NV * 4][3], qcol[TORUS_NU * TORUS_NV * 4][4];
        torus_expand(&m, m.quad, m.quad_count, &qpos[0][0], &qnrm[0][0], &qcol[0][0]);
        for (int with_color = 0; with_color < 2; with_color++) {
            array_cell(cell, 10.0f + 35 * cell); cell++;
            set_arrays(qpos, qnrm, qcol, with_color);
            glDrawArrays(GL_QUADS, 0, m.quad_count);
        }
        glShadeModel(GL_FLAT);
        array_cell(cell++, 100.0f);
        glDrawArrays(GL_QUADS, 0, m.quad_count);
    }
    scene_readpixels_check();
    return scene_end();
}
