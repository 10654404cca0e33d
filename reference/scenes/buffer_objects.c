/* Vertex arrays in buffer objects (GL 2.1 §2.9): every pointer an offset into
 * the bound array buffer (one interleaved buffer, and separate buffers),
 * indices from an element array buffer at an offset, data given by
 * glBufferData, glBufferSubData and written through glMapBuffer; lit torus
 * with colour material, glDrawArrays, glDrawElements, glDrawRangeElements. */
#include <stddef.h>

#include "array_common.h"

static torus_mesh m;

typedef struct {
    float n[3];
    GLubyte c[4];
    float p[3];
} vertex;

int main(int argc, char **argv)
{
    static vertex interleaved[TORUS_VERTS];
    static GLushort idx[8 + TORUS_NU * TORUS_NV * 6];
    static float flat_pos[TORUS_NU * TORUS_NV * 6][3], flat_nrm[TORUS_NU * TORUS_NV * 6][3],
        flat_col[TORUS_NU * TORUS_NV * 6][4];
    GLuint buf[5];
    int i, j;
    scene_begin(argc, argv, 160, 160);
    array_lit_setup();
    glEnable(GL_COLOR_MATERIAL);
    torus_build(&m, 0.45f, 0.18f);
    for (i = 0; i < TORUS_VERTS; i++) {
        memcpy(interleaved[i].n, m.nrm[i], 12);
        memcpy(interleaved[i].p, m.pos[i], 12);
        for (j = 0; j < 4; j++) interleaved[i].c[j] = (GLubyte)(m.col[i][j] * 255 + 0.5f);
    }
    for (i = 0; i < 8; i++) idx[i] = 0xffff; /* the draw starts past these */
    for (i = 0; i < m.tri_count; i++) idx[8 + i] = (GLushort)m.tri[i];
    torus_expand(&m, m.tri, m.tri_count, &flat_pos[0][0], &flat_nrm[0][0], &flat_col[0][0]);

    glGenBuffers(5, buf);
    /* buf[0]: the interleaved vertices, 64 bytes of padding first */
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, 64 + sizeof interleaved, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 64, sizeof interleaved, interleaved);
    /* buf[1]: indices at byte offset 16 */
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glNormalPointer(GL_FLOAT, sizeof(vertex), (void *)(64 + offsetof(vertex, n)));
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(vertex), (void *)(64 + offsetof(vertex, c)));
    glVertexPointer(3, GL_FLOAT, sizeof(vertex), (void *)(64 + offsetof(vertex, p)));
    glBindBuffer(GL_ARRAY_BUFFER, 0); /* the pointers keep their buffer */
    array_cell(0, 30.0f);
    glDrawElements(GL_TRIANGLES, m.tri_count, GL_UNSIGNED_SHORT, (void *)16);
    glShadeModel(GL_FLAT);
    array_cell(1, 75.0f);
    glDrawRangeElements(GL_TRIANGLES, 0, TORUS_VERTS - 1, m.tri_count, GL_UNSIGNED_SHORT, (void *)16);
    glShadeModel(GL_SMOOTH);

    /* separate buffers for positions, normals, colours, filled by glMapBuffer */
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, buf[2]);
    glBufferData(GL_ARRAY_BUFFER, sizeof flat_pos, NULL, GL_DYNAMIC_DRAW);
    memcpy(glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY), flat_pos, sizeof flat_pos);
    glUnmapBuffer(GL_ARRAY_BUFFER);
    glVertexPointer(3, GL_FLOAT, 0, 0);
    glBindBuffer(GL_ARRAY_BUFFER, buf[3]);
    glBufferData(GL_ARRAY_BUFFER, sizeof flat_nrm, flat_nrm, GL_STREAM_DRAW);
    glNormalPointer(GL_FLOAT, 0, 0);
    glBindBuffer(GL_ARRAY_BUFFER, buf[4]);
    glBufferData(GL_ARRAY_BUFFER, sizeof flat_col, flat_col, GL_STATIC_DRAW);
    glColorPointer(4, GL_FLOAT, 0, 0);
    array_cell(2, 120.0f);
    glDrawArrays(GL_TRIANGLES, 0, m.tri_count);
    /* the same with the colour array from client memory again */
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glColorPointer(4, GL_FLOAT, 0, flat_col);
    array_cell(3, 160.0f);
    glDrawArrays(GL_TRIANGLES, 0, m.tri_count);
    glDeleteBuffers(5, buf);
    scene_readpixels_check();
    return scene_end();
}
