/* clear_masks_common.h - the scene of clear_masks and clear_masks_depth16:
 * glClear with a colour mask per channel, with the depth mask off, and under
 * the scissor (a box inside the buffer, one past its edges, an empty one, one
 * covering it all); then quads drawn against the depth the clears left. */
#ifndef CLEAR_MASKS_COMMON_H
#define CLEAR_MASKS_COMMON_H
#include "scene.h"

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static int clear_masks_scene(int argc, char **argv, int depth_bits)
{
    scene_options o = {128, 96, OSMESA_RGBA, depth_bits, 1, 0};
    scene_begin_ext(argc, argv, &o);
    glEnable(GL_SCISSOR_TEST);
    /* A band per colour mask, cleared white over a grey base. */
    glScissor(0, 0, 128, 96);
    glClearColor(0.4f, 0.4f, 0.4f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(1.0f, 0.9f, 0.8f, 1.0f);
    glScissor(0, 64, 32, 32);
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(32, 64, 32, 32);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(64, 64, 32, 32);
    glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(96, 64, 100, 100); /* past the right and top edges */
    glColorMask(GL_TRUE, GL_TRUE, GL_FALSE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glScissor(50, 50, 0, 10); /* empty */
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* Depth: a scissored clear to several depths, one with the depth mask
       off (keeps the old depth), and the colour masked off entirely. */
    glClearDepth(0.3);
    glScissor(-10, -10, 40, 50);
    glClear(GL_DEPTH_BUFFER_BIT);
    glClearDepth(0.1);
    glScissor(30, 0, 30, 40);
    glClear(GL_DEPTH_BUFFER_BIT);
    glClearDepth(1.0 / 3.0);
    glScissor(60, 0, 30, 40);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glClearDepth(0.0);
    glScissor(90, 0, 38, 40);
    glClearColor(0.2f, 0.7f, 0.5f, 1.0f);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    glDepthMask(GL_TRUE);

    /* Quads at depths around the cleared values, drawn with GL_LESS: each
       shows where its depth passes; scissored to the lower half, then the
       whole buffer with a box covering it (the direct clear). */
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 128, 0, 96, 0, -1); /* z = window depth */
    glMatrixMode(GL_MODELVIEW);
    glColor3f(0.9f, 0.2f, 0.2f);
    quad(0, 4, 128, 12, 0.29f);
    glColor3f(0.2f, 0.9f, 0.2f);
    quad(0, 14, 128, 22, 0.31f);
    glColor3f(0.2f, 0.2f, 0.9f);
    quad(0, 24, 128, 32, 0.0999999f);
    glColor3f(0.9f, 0.9f, 0.2f);
    quad(0, 34, 128, 38, 0.3333333f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 128, 96);
    glClearDepth(0.7);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glScissor(0, 40, 128, 20);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColor3f(0.9f, 0.5f, 0.1f);
    quad(10, 42, 60, 58, 0.6999999f);
    quad(70, 42, 120, 58, 0.7000001f);

    /* A box covering the buffer clears directly: depth 1/3 is 0x555555
       there (the quad clear gives 0x555554), which a quad at 1/3 matches
       under GL_EQUAL. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 128, 96);
    glClearDepth(1.0 / 3.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_EQUAL);
    glColor3f(0.6f, 0.3f, 0.9f);
    quad(10, 70, 118, 90, 1.0f / 3.0f);
    glDepthFunc(GL_LESS);
    scene_readpixels_check();
    return scene_end();
}
#endif
