/* Long indexed GL_TRIANGLE_STRIP, GL_QUADS, GL_QUAD_STRIP, GL_TRIANGLE_FAN
 * and GL_POLYGON draws (32-bit indices, more than 1024 each), and long
 * glDrawArrays fans and polygons: Mesa's draw module splits them into
 * segments (1024 indices, strips and quad strips overlapping by 2, fans and
 * polygons repeating the first index) and clip-tests each alone. Slivers
 * (indexed_common.h) near the segment edges vanish only in the segment that
 * uses a vertex outside the view. Repeated indices make the other
 * primitives degenerate. */
#include "indexed_common.h"

#include <stdlib.h>
#include <string.h>

#define MAXV 1000
#define MAXI 8000 /* fans up to 5000 indices */

static float pos[MAXV][2], fanpos[MAXI][2];
static unsigned idx[MAXI];
static int nv, cell;

static int add_vertex(float x, float y)
{
    pos[nv][0] = x;
    pos[nv][1] = y;
    return nv++;
}
static void block_begin(float fx, float fy)
{
    nv = 0;
    add_vertex(fx, fy); /* vertex 0: the filler or the hub */
    add_vertex(5000, 100); /* vertex 1: outside */
}
/* The next grid cell's sliver (direction 0): its vertices A, B, C. */
static void next_sliver(unsigned v[3])
{
    float s[3][2];
    int k;
    sliver_make(s, 0, (cell % 10) * 25 + 2.5f, 60 + (cell / 10) * 12 + 1.5f);
    cell++;
    for (k = 0; k < 3; k++) v[k] = add_vertex(s[k][0], s[k][1]);
}
static void next_row(void) { cell = (cell + 9) / 10 * 10; }
static void draw(GLenum mode, int n)
{
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glDrawElements(mode, n, GL_UNSIGNED_INT, idx);
}

/* Units of 6 indices: a sliver (A A C B B B: the odd triangle A C B, which
 * a strip turns round to A B C), an outside unit, or filler. */
static void strip(void)
{
    static const int slivers[] = {0, 100, 170, 171, 250, 340, 341, 400, 510, 511, 600};
    int u, i, n = 601 * 6;
    unsigned v[3];
    block_begin(128.5f, 255.5f);
    memset(idx, 0, sizeof(unsigned) * n);
    for (i = 0; i < (int)(sizeof slivers / sizeof slivers[0]); i++) {
        u = slivers[i];
        next_sliver(v);
        idx[6 * u] = idx[6 * u + 1] = v[0];
        idx[6 * u + 2] = v[2];
        idx[6 * u + 3] = idx[6 * u + 4] = idx[6 * u + 5] = v[1];
    }
    for (i = 0; i < 6; i++) idx[6 * 300 + i] = 1; /* segment 1 */
    next_row();
    draw(GL_TRIANGLE_STRIP, n);
}

/* Quad q = (A, B, B, C): triangles (A, B, C) and a degenerate one. */
static void quads(void)
{
    static const int slivers[] = {0, 100, 255, 256, 300, 511, 512, 700, 767, 768};
    int q, i, n = 800 * 4;
    unsigned v[3];
    block_begin(128.5f, 255.5f);
    memset(idx, 0, sizeof(unsigned) * n);
    for (i = 0; i < (int)(sizeof slivers / sizeof slivers[0]); i++) {
        q = slivers[i];
        next_sliver(v);
        idx[4 * q] = v[0];
        idx[4 * q + 1] = idx[4 * q + 2] = v[1];
        idx[4 * q + 3] = v[2];
    }
    for (i = 0; i < 4; i++) idx[4 * 400 + i] = 1; /* segment 1 */
    next_row();
    draw(GL_QUADS, n);
}

/* Units of 3 pairs: (A, A) (A, B) (C, C); the middle quad holds A B C. */
static void quad_strip(void)
{
    static const int slivers[] = {0, 100, 169, 170, 200, 339, 340, 341, 400, 510, 511};
    int u, i, n = 600 * 6;
    unsigned v[3];
    block_begin(128.5f, 255.5f);
    memset(idx, 0, sizeof(unsigned) * n);
    for (i = 0; i < (int)(sizeof slivers / sizeof slivers[0]); i++) {
        u = slivers[i];
        next_sliver(v);
        idx[6 * u] = idx[6 * u + 1] = idx[6 * u + 2] = v[0];
        idx[6 * u + 3] = v[1];
        idx[6 * u + 4] = idx[6 * u + 5] = v[2];
    }
    for (i = 0; i < 6; i++) idx[6 * 250 + i] = 1; /* segment 1 */
    next_row();
    draw(GL_QUAD_STRIP, n);
}

/* A fan around the hub (index 0 = vertex 0): triangle t = (0, t+1, t+2);
 * the slivers of the eight directions at these triangles, the hub between
 * them, the outside vertex in segment 2 (triangles 2044..3065). */
static void fan(GLenum mode, int arrays, int n, float hx, float hy)
{
    static const int slivers[8] = {10, 1019, 1022, 1500, 2041, 2044, 2500, 3064};
    int i;
    block_begin(hx, hy);
    memset(idx, 0, sizeof(unsigned) * n);
    for (i = 0; i < 8; i++) {
        float s[3][2];
        int t = slivers[i];
        sliver_make(s, i, hx, hy);
        idx[t + 1] = add_vertex(s[1][0], s[1][1]);
        idx[t + 2] = add_vertex(s[2][0], s[2][1]);
    }
    idx[2101] = 1;
    if (arrays) {
        for (i = 0; i < n; i++) {
            fanpos[i][0] = pos[idx[i]][0];
            fanpos[i][1] = pos[idx[i]][1];
        }
        glVertexPointer(2, GL_FLOAT, 0, fanpos);
        glDrawArrays(mode, 0, n);
    } else {
        draw(mode, n);
    }
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    glEnable(GL_CULL_FACE);
    glColor3f(0.3f, 0.8f, 0.5f);
    glEnableClientState(GL_VERTEX_ARRAY);
    strip();
    quads();
    quad_strip();
    /* indexed fans and polygons: segments of 1024 indices; glDrawArrays:
     * one segment up to 4096 vertices (all vanish), else 1024 */
    fan(GL_TRIANGLE_FAN, 0, 3200, 30.5f, 30.5f);
    fan(GL_POLYGON, 0, 3200, 90.5f, 30.5f);
    fan(GL_TRIANGLE_FAN, 1, 5000, 150.5f, 30.5f);
    fan(GL_POLYGON, 1, 3200, 210.5f, 30.5f);
    /* the other way round, first-vertex convention */
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    fan(GL_POLYGON, 0, 5000, 30.5f, 150.5f);
    fan(GL_TRIANGLE_FAN, 0, 4000, 90.5f, 150.5f);
    fan(GL_POLYGON, 1, 5000, 150.5f, 150.5f);
    fan(GL_TRIANGLE_FAN, 1, 4096, 210.5f, 150.5f);
    scene_readpixels_check();
    return scene_end();
}
