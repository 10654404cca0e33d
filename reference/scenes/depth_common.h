/* depth_common.h - overlapping depth-tested geometry for the depth_func_*
 * scenes.  With glOrtho(0,128,0,128,-1,1) a vertex z maps to window depth
 * (1 - z) / 2, so z = -1 lands exactly on the cleared depth 1.0. */
#ifndef DEPTH_COMMON_H
#define DEPTH_COMMON_H
#include "scene.h"

static inline void depth_begin(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

/* Slanted quad: depth goes from z0 (left) to z1 (right). */
static inline void depth_quad(float x0, float y0, float x1, float y1, float z0, float z1,
                              const float c0[3], const float c1[3])
{
    glBegin(GL_QUADS);
    glColor3fv(c0); glVertex3f(x0, y0, z0);
    glColor3fv(c1); glVertex3f(x1, y0, z1);
    glColor3fv(c1); glVertex3f(x1, y1, z1);
    glColor3fv(c0); glVertex3f(x0, y1, z0);
    glEnd();
}

static inline void depth_draw(GLenum func)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, green[3] = {0, 1, 0},
                       cyan[3] = {0, 1, 1}, blue[3] = {0, 0, 1}, white[3] = {1, 1, 1},
                       grey[3] = {0.5f, 0.5f, 0.5f}, magenta[3] = {1, 0, 1};
    /* base geometry with GL_LESS: two halves of one slanted surface */
    depth_quad(8, 8, 120, 64, 0.6f, -0.6f, red, yellow);
    depth_quad(8, 64, 120, 112, 0.6f, -0.6f, red, yellow);

    glDepthFunc(func);
    /* crossing slope over the lower half */
    depth_quad(8, 16, 120, 56, -0.6f, 0.6f, green, cyan);
    /* exactly the same vertices as the upper half: equal depth everywhere */
    depth_quad(8, 64, 120, 112, 0.6f, -0.6f, blue, white);
    /* constant depth 0.5 strip straddling both halves */
    depth_quad(56, 20, 72, 108, 0.0f, 0.0f, magenta, magenta);
    /* on the cleared depth (z = -1, depth 1.0) and just in front of it */
    depth_quad(0, 116, 64, 126, -1.0f, -1.0f, grey, grey);
    depth_quad(64, 116, 128, 126, -0.999f, -0.999f, white, grey);
    glDepthFunc(GL_LESS);
}
#endif
