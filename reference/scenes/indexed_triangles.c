/* How Mesa's draw module splits an indexed GL_TRIANGLES draw, shown by
 * slivers (indexed_common.h) with culling on: a sliver vanishes when the
 * segment that holds it goes through the clipping pipeline.
 *   - A draw is drawn whole, fetching and clip-testing every vertex of its
 *     index range (used or not), when the range is known (client arrays, or
 *     glDrawRangeElements, its end clamped to the index type), no wider than
 *     the draw, and the draw has at most 4096 indices (16-bit, from 0) or
 *     1024 (any other), and, in an element array buffer, ends before the
 *     buffer's last index.
 *   - Otherwise it is split into segments of 1023 indices (341 triangles),
 *     each clip-tested on the vertices it uses.
 * One row per case; a vertex outside the view is referenced in some
 * segments only, or not at all. */
#include "indexed_common.h"

#include <stdlib.h>
#include <string.h>

#define MAXB 4000
#define MAXI 13000

static float pos[MAXB][2];
static unsigned idx[MAXI];
static unsigned short idx16[MAXI];
static unsigned char idx8[MAXI];
static int nv, ni, cell;

static void block_begin(void)
{
    nv = 0;
    pos[0][0] = 128.5f; /* vertex 0: the filler, inside; (0,0,0) draws nothing */
    pos[0][1] = 255.5f;
    nv = 1;
}
static int add_vertex(float x, float y)
{
    pos[nv][0] = x;
    pos[nv][1] = y;
    return nv++;
}
static void fill(int triangles)
{
    ni = 3 * triangles;
    memset(idx, 0, sizeof(unsigned) * ni);
}
/* A sliver as triangle t of the draw, in the next cell. */
static void sliver_at(int t)
{
    float v[3][2];
    int k;
    sliver_make(v, 0, (cell % 10) * 25 + 2.5f, (cell / 10) * 12 + 1.5f);
    cell++;
    for (k = 0; k < 3; k++) idx[3 * t + k] = add_vertex(v[k][0], v[k][1]);
}
/* A vertex outside the view; referenced as the degenerate triangle t if t >= 0. */
static void outside_at(int t)
{
    int o = add_vertex(5000, 100);
    if (t >= 0) idx[3 * t] = idx[3 * t + 1] = idx[3 * t + 2] = o;
}
static void next_row(void) { cell = (cell + 9) / 10 * 10; }

static void arrays_client(void)
{
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glVertexPointer(2, GL_FLOAT, 0, pos);
}
static void arrays_vbo(GLuint b)
{
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBufferData(GL_ARRAY_BUFFER, sizeof(float) * 2 * nv, pos, GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, 0, (void *)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}
static const void *indices_as(GLenum type)
{
    int i;
    for (i = 0; i < ni; i++) {
        idx16[i] = (unsigned short)idx[i];
        idx8[i] = (unsigned char)idx[i];
    }
    return type == GL_UNSIGNED_INT ? (const void *)idx : type == GL_UNSIGNED_SHORT ? (const void *)idx16 : (const void *)idx8;
}
static int type_size(GLenum type) { return type == GL_UNSIGNED_INT ? 4 : type == GL_UNSIGNED_SHORT ? 2 : 1; }

/* The index list in an element array buffer holding `spare` more indices. */
static void draw_from_ebo(GLuint e, GLenum type, int spare)
{
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, e);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, type_size(type) * (ni + spare), NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, type_size(type) * ni, indices_as(type));
    glDrawElements(GL_TRIANGLES, ni, type, (void *)0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

/* A long draw: slivers at these triangles, outside vertices in two segments. */
static const int long_slivers[] = {0, 200, 339, 340, 341, 342, 600, 681, 682, 700, 1022, 1023, 1100, 1363, 1364,
                                   1400, 1704, 1705, 1706, 2045, 2046, 2100, 2386, 2387, 3000, 3999};

static void long_draw(GLenum type, int vbo, int ebo, GLuint b, GLuint e)
{
    int i;
    block_begin();
    fill(4000);
    for (i = 0; i < (int)(sizeof long_slivers / sizeof long_slivers[0]); i++) sliver_at(long_slivers[i]);
    next_row();
    outside_at(690);  /* segment 682..1022 */
    outside_at(1500); /* segment 1364..1704 */
    if (vbo) arrays_vbo(b); else arrays_client();
    if (ebo) draw_from_ebo(e, type, 0);
    else glDrawElements(GL_TRIANGLES, ni, type, indices_as(type));
}

/* A short draw: `n` slivers among `triangles`, and vertex 1, inside the
 * index range, outside the view but used by none. */
static void short_block(int triangles, int n)
{
    int i;
    block_begin();
    fill(triangles);
    outside_at(-1);
    for (i = 0; i < n; i++) sliver_at(i * (triangles / n));
    next_row();
}

int main(int argc, char **argv)
{
    GLuint b[4], e[4];
    int i;
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    scene_srand(11);
    glEnable(GL_CULL_FACE);
    glColor3f(0.9f, 0.6f, 0.3f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glGenBuffers(4, b);
    glGenBuffers(4, e);

    /* rows 0-2: long draws in segments: 32-bit client; 16-bit from buffers */
    long_draw(GL_UNSIGNED_INT, 0, 0, 0, 0);
    long_draw(GL_UNSIGNED_SHORT, 1, 1, b[0], e[0]);

    /* 1300 triangles, 3900 16-bit indices from 0, client arrays: drawn whole,
     * the unused outside vertex sends it through the pipeline; as 32-bit
     * indices it is split (more than 1024) and nothing vanishes. */
    short_block(1300, 10);
    arrays_client();
    glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_SHORT, indices_as(GL_UNSIGNED_SHORT));
    short_block(1300, 10);
    arrays_client();
    glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_INT, indices_as(GL_UNSIGNED_INT));

    /* the same 16-bit list with every index one higher (vertex 0 unused):
     * min > 0 allows only 1024 indices, so it is split */
    short_block(1300, 10);
    memmove(pos + 1, pos, sizeof(pos[0]) * nv);
    nv++;
    for (i = 0; i < ni; i++) idx[i]++;
    arrays_client();
    glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_SHORT, indices_as(GL_UNSIGNED_SHORT));

    /* 300 triangles from a buffer object: no range known, one segment of the
     * vertices used; glDrawRangeElements gives the range: drawn whole. */
    short_block(300, 10);
    arrays_vbo(b[1]);
    glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_INT, indices_as(GL_UNSIGNED_INT));
    short_block(300, 10);
    arrays_vbo(b[2]);
    glDrawRangeElements(GL_TRIANGLES, 0, nv - 1, ni, GL_UNSIGNED_INT, indices_as(GL_UNSIGNED_INT));
    /* a range wider than the draw: split, nothing vanishes */
    short_block(300, 10);
    arrays_client();
    glDrawRangeElements(GL_TRIANGLES, 0, 5000, ni, GL_UNSIGNED_INT, indices_as(GL_UNSIGNED_INT));

    /* 8-bit indices: the range's end is clamped to 255, which makes it no
     * wider than the 300 indices: drawn whole */
    short_block(100, 10);
    arrays_client();
    glDrawRangeElements(GL_TRIANGLES, 0, 300, ni, GL_UNSIGNED_BYTE, indices_as(GL_UNSIGNED_BYTE));

    /* client arrays, indices in a buffer that ends with the list: split; one
     * index longer: drawn whole */
    short_block(300, 10);
    arrays_client();
    draw_from_ebo(e[1], GL_UNSIGNED_INT, 0);
    short_block(300, 10);
    arrays_client();
    draw_from_ebo(e[2], GL_UNSIGNED_SHORT, 1);

    /* 8-bit indices, 400 triangles: more than 1024 indices, split into
     * 341-triangle segments; the outside vertex is used in the second only */
    block_begin();
    fill(400);
    for (i = 0; i < 10; i++) sliver_at(i < 5 ? 300 + 10 * i : 341 + 10 * i);
    next_row();
    outside_at(399);
    arrays_client();
    glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_BYTE, indices_as(GL_UNSIGNED_BYTE));

    /* glMultiDrawElements: list 0 uses slivers only, list 1 the outside
     * vertex; the range Mesa computes is both lists' */
    {
        static unsigned list1[3];
        const void *lists[2];
        GLsizei counts[2];
        block_begin();
        fill(100);
        for (i = 0; i < 10; i++) sliver_at(10 * i);
        next_row();
        outside_at(-1);
        list1[0] = list1[1] = list1[2] = nv - 1;
        lists[0] = idx;
        lists[1] = list1;
        counts[0] = ni;
        counts[1] = 3;
        arrays_client();
        glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, lists, 2);
        /* the same lists drawn one by one: list 0's range lacks the vertex */
        block_begin();
        fill(100);
        for (i = 0; i < 10; i++) sliver_at(10 * i);
        next_row();
        outside_at(-1);
        list1[0] = list1[1] = list1[2] = nv - 1;
        arrays_client();
        glDrawElements(GL_TRIANGLES, ni, GL_UNSIGNED_INT, idx);
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, list1);
    }
    scene_readpixels_check();
    return scene_end();
}
