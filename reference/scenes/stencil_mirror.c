/* A stencil mirror: the mirror's pixels are marked in the stencil buffer, the
 * lit object is drawn reflected only where the mark is, then the mirror
 * frame (outside the mark) and the object itself. */
#include <GL/glu.h>
#include "scene.h"

static void object(GLUquadric *q)
{
    GLfloat red[4] = {0.9f, 0.3f, 0.2f, 1}, blue[4] = {0.2f, 0.4f, 0.9f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    glPushMatrix();
    glTranslatef(0, 0.6f, 0);
    gluSphere(q, 0.45, 24, 16);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    glTranslatef(0.55f, -0.2f, 0.3f);
    gluSphere(q, 0.22, 16, 12);
    glPopMatrix();
}

static void mirror_quad(void)
{
    glBegin(GL_QUADS);
    glVertex3f(-1.0f, 0, -1.0f); glVertex3f(-1.0f, 0, 1.0f); glVertex3f(1.0f, 0, 1.0f); glVertex3f(1.0f, 0, -1.0f);
    glEnd();
}

int main(int argc, char **argv)
{
    scene_options o = {160, 128, OSMESA_RGBA, 24, 1, 0};
    GLfloat light[4] = {1, 2, 2, 0}, below[4] = {1, -2, 2, 0};
    GLUquadric *q;
    scene_set_stencil_bits(8);
    scene_begin_ext(argc, argv, &o);
    q = gluNewQuadric();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, 160.0 / 128.0, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 2.2, 4.0, 0, 0.2, 0, 0, 1, 0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* 1. mark the mirror: stencil 1, no colour, no depth */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glPushMatrix();
    glScalef(0.8f, 1, 0.8f);
    mirror_quad();
    glPopMatrix();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);

    /* 2. the reflection, where the stencil is 1 */
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glPushMatrix();
    glScalef(1, -1, 1);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glFrontFace(GL_CW);
    object(q);
    glFrontFace(GL_CCW);
    glPopMatrix();
    glDisable(GL_LIGHTING);

    /* 3. the frame around it, where the stencil is not 1 */
    glStencilFunc(GL_NOTEQUAL, 1, 0xff);
    glColor3f(0.5f, 0.45f, 0.35f);
    mirror_quad();

    /* 4. the object itself, everywhere */
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_LIGHTING);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    (void)below;
    object(q);
    gluDeleteQuadric(q);
    scene_readpixels_check();
    return scene_end();
}
