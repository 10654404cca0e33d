/* Shared by the indexed_* scenes: slivers, triangles that show whether Mesa's
 * draw module ran its clipping pipeline for the draw segment that holds them.
 *
 * A sliver is the triangle (A, B, C) with A at a pixel centre, C = A + 10·d
 * and B = A + 2·d plus a tiny offset: exactly collinear in float, so the draw
 * module's float cull (GL_CULL_FACE, zero area counts as back-facing) drops
 * it, but llvmpipe's snapping moves B off the line, and its own fixed-point
 * setup draws 9 pixels of it. So with culling on, a sliver is drawn unless
 * its segment has a vertex outside the view volume. The eight directions d
 * and the offset and vertex order that do this were measured on Mesa 22.3.6;
 * every sliver uses one pixel centre A and fans out from it, so a fan's hub
 * can be A.
 * The window must be 256 x 256 in pixel units (scene_ortho_pixels) so that
 * every transform is exact. */
#ifndef GLFX_INDEXED_COMMON_H
#define GLFX_INDEXED_COMMON_H

#include "scene.h"

static const int sliver_dir[8][2] = {{2, 1}, {-2, 1}, {2, -1}, {-2, -1}, {1, 2}, {-1, 2}, {1, -2}, {-1, -2}};
/* Offset signs (x, y) and whether the order is (A, B, C) (else (A, C, B)). */
static const int sliver_var[8][3] = {{1, 1, 1}, {1, -1, 1}, {1, -1, 0}, {1, 1, 0},
                                     {-1, -1, 1}, {-1, 1, 1}, {-1, 1, 0}, {-1, -1, 0}};

/* Writes the sliver of direction `dir` from the pixel centre (ax, ay) into
 * v[0..2] (x, y) in drawing order, A first. */
static inline void sliver_make(float v[3][2], int dir, float ax, float ay)
{
    float dx = (float)sliver_dir[dir][0], dy = (float)sliver_dir[dir][1];
    float ox = sliver_var[dir][0] / 256.0f, oy = sliver_var[dir][1] / 512.0f;
    float bx, by, cx = ax + 10 * dx, cy = ay + 10 * dy;
    int abc = sliver_var[dir][2];
    if (dy == 2 || dy == -2) {
        ox = sliver_var[dir][0] / 512.0f;
        oy = sliver_var[dir][1] / 256.0f;
    }
    bx = ax + 2 * dx + ox;
    by = ay + 2 * dy + oy;
    v[0][0] = ax;
    v[0][1] = ay;
    v[abc ? 1 : 2][0] = bx;
    v[abc ? 1 : 2][1] = by;
    v[abc ? 2 : 1][0] = cx;
    v[abc ? 2 : 1][1] = cy;
}

#endif
