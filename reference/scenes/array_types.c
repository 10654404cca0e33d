/* Every component type of the vertex, normal and colour arrays (table 2.9:
 * normalized integer normals and colours, signed and unsigned), each with a
 * padded stride: positions and normals on a lit torus, colours unlit (sizes
 * 3 and 4), so each converted value decides the pixels on its own. */
#include "array_common.h"

static torus_mesh m;

/* Writes n elements of `size` components of type `type` at `stride` bytes,
 * value = src * scale (rounded, clamped to the type). */
static void pack(void *dst, GLenum type, int size, int stride, const float *src, int src_size, int n, double scale)
{
    int k, j;
    for (k = 0; k < n; k++)
        for (j = 0; j < size; j++) {
            char *p = (char *)dst + k * stride;
            double x = src[k * src_size + j] * scale;
            double r = floor(x + 0.5);
            switch (type) {
            case GL_BYTE: { GLbyte v = (GLbyte)(r > 127 ? 127 : r < -127 ? -127 : r); memcpy(p + j, &v, 1); break; }
            case GL_UNSIGNED_BYTE: { GLubyte v = (GLubyte)(r > 255 ? 255 : r < 0 ? 0 : r); memcpy(p + j, &v, 1); break; }
            case GL_SHORT: { GLshort v = (GLshort)(r > 32767 ? 32767 : r < -32767 ? -32767 : r); memcpy(p + 2 * j, &v, 2); break; }
            case GL_UNSIGNED_SHORT: { GLushort v = (GLushort)(r > 65535 ? 65535 : r < 0 ? 0 : r); memcpy(p + 2 * j, &v, 2); break; }
            case GL_INT: { GLint v = (GLint)(r > 2147483647.0 ? 2147483647.0 : r < -2147483647.0 ? -2147483647.0 : r); memcpy(p + 4 * j, &v, 4); break; }
            case GL_UNSIGNED_INT: { GLuint v = (GLuint)(r > 4294967295.0 ? 4294967295.0 : r < 0 ? 0 : r); memcpy(p + 4 * j, &v, 4); break; }
            case GL_FLOAT: { GLfloat v = (GLfloat)x; memcpy(p + 4 * j, &v, 4); break; }
            case GL_DOUBLE: { GLdouble v = x; memcpy(p + 8 * j, &v, 8); break; }
            }
        }
}

static double norm_scale(GLenum type)
{
    switch (type) {
    case GL_BYTE: return 127;
    case GL_UNSIGNED_BYTE: return 255;
    case GL_SHORT: return 32767;
    case GL_UNSIGNED_SHORT: return 65535;
    case GL_INT: return 2147483647.0;
    case GL_UNSIGNED_INT: return 4294967295.0;
    default: return 1;
    }
}

static char vbuf[TORUS_VERTS * 48], nbuf[TORUS_VERTS * 48], cbuf[TORUS_VERTS * 48];

static void draw(GLenum vtype, GLenum ntype, GLenum ctype, int csize)
{
    const int pad = 4; /* every array has a stride with padding */
    int vb = vtype == GL_DOUBLE ? 8 : vtype == GL_SHORT ? 2 : 4;
    int nb = ntype == GL_DOUBLE ? 8 : ntype == GL_BYTE ? 1 : ntype == GL_SHORT ? 2 : 4;
    int cb = ctype == GL_DOUBLE ? 8 : (ctype == GL_BYTE || ctype == GL_UNSIGNED_BYTE) ? 1
             : (ctype == GL_SHORT || ctype == GL_UNSIGNED_SHORT) ? 2 : 4;
    double vscale = (vtype == GL_SHORT || vtype == GL_INT) ? 1000.0 : 1.0;
    pack(vbuf, vtype, 3, 3 * vb + pad, &m.pos[0][0], 3, TORUS_VERTS, vscale);
    pack(nbuf, ntype, 3, 3 * nb + pad, &m.nrm[0][0], 3, TORUS_VERTS, norm_scale(ntype));
    pack(cbuf, ctype, csize, csize * cb + pad, &m.col[0][0], 4, TORUS_VERTS, norm_scale(ctype));
    glVertexPointer(3, vtype, 3 * vb + pad, vbuf);
    glNormalPointer(ntype, 3 * nb + pad, nbuf);
    glColorPointer(csize, ctype, csize * cb + pad, cbuf);
    if (vscale != 1.0) glScalef(0.001f, 0.001f, 0.001f);
    glDrawElements(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_INT, m.tri);
}

int main(int argc, char **argv)
{
    static const GLenum vtypes[] = {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
    static const GLenum ntypes[] = {GL_BYTE, GL_SHORT, GL_INT, GL_DOUBLE};
    static const GLenum ctypes[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                                    GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE};
    int cell = 0, i;
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    torus_build(&m, 0.45f, 0.18f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    for (i = 0; i < 4; i++) { array_cell(cell, 20.0f + 23 * cell); cell++; draw(vtypes[i], GL_FLOAT, GL_FLOAT, 4); }
    for (i = 0; i < 4; i++) { array_cell(cell, 20.0f + 23 * cell); cell++; draw(GL_FLOAT, ntypes[i], GL_FLOAT, 4); }
    glDisable(GL_LIGHTING);
    glEnableClientState(GL_COLOR_ARRAY);
    for (i = 0; i < 8; i++) { array_cell(cell, 20.0f + 23 * cell); cell++; draw(GL_FLOAT, GL_FLOAT, ctypes[i], i % 2 ? 3 : 4); }
    scene_readpixels_check();
    return scene_end();
}
