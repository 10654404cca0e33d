/* glCopyPixels of depth and stencil, then geometry tested against them: a
 * lit sphere writes depth and marks the stencil; the depth and the stencil
 * are copied beside it (zoomed, overlapping, under a write mask, the depth
 * copy coloured with the current colour), and both together; then a quad is
 * drawn through the depth test and a second one through the stencil test. */
#include <GL/glu.h>

#include "scene.h"

void glWindowPos2i(GLint x, GLint y);
void glWindowPos3f(GLfloat x, GLfloat y, GLfloat z);

int main(int argc, char **argv)
{
    scene_options o = {160, 128, OSMESA_RGBA, 24, 1, 0};
    scene_set_stencil_bits(8);
    scene_begin_ext(argc, argv, &o);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 160, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 3, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);

    /* A lit sphere: depth and stencil 3 where it is drawn. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    GLUquadric *q = gluNewQuadric();
    glColor3f(0.9f, 0.6f, 0.3f);
    glPushMatrix();
    glTranslatef(30, 34, 0);
    glScalef(26, 26, 0.9f);
    gluSphere(q, 1.0, 28, 18);
    glPopMatrix();
    gluDeleteQuadric(q);
    glDisable(GL_LIGHTING);
    glDisable(GL_STENCIL_TEST);

    /* The depth copied: with GL_ALWAYS, zoomed, coloured with the current colour. */
    glDepthFunc(GL_ALWAYS);
    glColor3f(0.2f, 0.5f, 0.8f);
    glWindowPos2i(66, 6);
    glColor3f(0.7f, 0.3f, 0.5f);
    glPixelZoom(1.5f, 1.0f);
    glCopyPixels(4, 8, 52, 52, GL_DEPTH);
    glPixelZoom(1, 1);
    /* Overlapping, through GL_LESS, and with depth scale/bias set (not applied). */
    glDepthFunc(GL_LESS);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, -0.3f);
    glColor3f(0.3f, 0.8f, 0.4f);
    glWindowPos3f(14, 20, 0);
    glCopyPixels(4, 8, 52, 52, GL_DEPTH);
    glPixelTransferf(GL_DEPTH_SCALE, 1);
    glPixelTransferf(GL_DEPTH_BIAS, 0);

    /* The stencil copied: zoomed 2 x 0.75 under a write mask, and overlapping. */
    glStencilMask(0x01);
    glPixelZoom(-0.75f, 0.75f);
    glWindowPos2i(150, 70);
    glCopyPixels(4, 8, 52, 52, GL_STENCIL);
    glStencilMask(0xff);
    glPixelZoom(1, 1);
    glWindowPos2i(10, 12);
    glCopyPixels(4, 8, 52, 52, GL_STENCIL);
    /* Both, into the top-left corner, partly from outside the buffer. */
    glWindowPos2i(0, 80);
    glCopyPixels(-10, 8, 60, 52, GL_DEPTH_STENCIL);

    /* A quad behind part of the copied depth, then one through the stencil. */
    glDepthFunc(GL_LESS);
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.9f, 0.2f);
    glVertex3f(0, 0, 0.1f);
    glColor3f(0.2f, 0.9f, 0.9f);
    glVertex3f(160, 0, -0.6f);
    glColor3f(0.9f, 0.2f, 0.9f);
    glVertex3f(160, 128, -0.6f);
    glColor3f(0.2f, 0.2f, 0.9f);
    glVertex3f(0, 128, 0.1f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0x01);
    glColor3f(0.8f, 0.3f, 0.2f);
    glRectf(0, 60, 160, 128);
    glStencilFunc(GL_EQUAL, 3, 0xff);
    glColor3f(0.2f, 0.3f, 0.8f);
    glRectf(0, 0, 160, 60);

    scene_readpixels_check();
    return scene_end();
}
