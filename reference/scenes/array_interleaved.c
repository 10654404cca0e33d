/* glInterleavedArrays, all 14 formats (table 2.5), each drawn with
 * glDrawElements: formats with a normal lit, the others unlit; colours from
 * the format where it has one; texture coordinates are set but unused. */
#include "array_common.h"

static torus_mesh m;
static float block[TORUS_VERTS * 16];

static void fill(GLenum format, int *stride_out)
{
    int has_t = 0, t = 0, c = 0, n = 0, vsz = 3, i, k;
    int c_ub = 0;
    switch (format) {
    case GL_V2F: vsz = 2; break;
    case GL_V3F: break;
    case GL_C4UB_V2F: c = 1; c_ub = 1; vsz = 2; break;
    case GL_C4UB_V3F: c = 1; c_ub = 1; break;
    case GL_C3F_V3F: c = 3; break;
    case GL_N3F_V3F: n = 1; break;
    case GL_C4F_N3F_V3F: c = 4; n = 1; break;
    case GL_T2F_V3F: t = 2; break;
    case GL_T4F_V4F: t = 4; vsz = 4; break;
    case GL_T2F_C4UB_V3F: t = 2; c = 1; c_ub = 1; break;
    case GL_T2F_C3F_V3F: t = 2; c = 3; break;
    case GL_T2F_N3F_V3F: t = 2; n = 1; break;
    case GL_T2F_C4F_N3F_V3F: t = 2; c = 4; n = 1; break;
    case GL_T4F_C4F_N3F_V4F: t = 4; c = 4; n = 1; vsz = 4; break;
    }
    has_t = t > 0;
    (void)has_t;
    int floats = t + (c_ub ? 1 : c) + (n ? 3 : 0) + vsz;
    for (i = 0; i < TORUS_VERTS; i++) {
        float *e = block + i * floats;
        k = 0;
        for (int j = 0; j < t; j++) e[k++] = 0.25f * j;
        if (c_ub) {
            unsigned char ub[4];
            for (int j = 0; j < 4; j++) ub[j] = (unsigned char)(m.col[i][j] * 255 + 0.5f);
            memcpy(&e[k++], ub, 4);
        } else {
            for (int j = 0; j < c; j++) e[k++] = m.col[i][j];
        }
        if (n) for (int j = 0; j < 3; j++) e[k++] = m.nrm[i][j];
        for (int j = 0; j < 3 && j < vsz; j++) e[k++] = m.pos[i][j];
        if (vsz == 4) e[k++] = 1.0f;
    }
    *stride_out = floats * 4;
    if (n) glEnable(GL_LIGHTING); else glDisable(GL_LIGHTING);
}

int main(int argc, char **argv)
{
    static const GLenum formats[14] = {GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F,
                                       GL_C4F_N3F_V3F, GL_T2F_V3F, GL_T4F_V4F, GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F,
                                       GL_T2F_N3F_V3F, GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F};
    int i, stride;
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    glEnable(GL_COLOR_MATERIAL);
    torus_build(&m, 0.45f, 0.18f);
    glColor3f(0.8f, 0.5f, 0.2f);
    for (i = 0; i < 14; i++) {
        fill(formats[i], &stride);
        array_cell(i, 20.0f + 23 * i);
        /* an explicit stride for the even formats, 0 (packed) for the odd */
        glInterleavedArrays(formats[i], i % 2 ? 0 : stride, block);
        glDrawElements(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_INT, m.tri);
    }
    scene_readpixels_check();
    return scene_end();
}
