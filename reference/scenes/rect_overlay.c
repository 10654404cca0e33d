/* glRect overlays on a lit scene, as GLUT programs draw HUD panels: a lit
 * sphere and torus in perspective, then in a pixel projection rectangles in
 * every glRect form. Some are lit by a positional light with a local viewer,
 * so that the four corners differ: under GL_FLAT the provoking corner shows
 * (Mesa draws a glRect as a GL_QUADS quad, corner 4), under GL_SMOOTH the
 * split. Some go into a display list with a glBegin/glEnd quad beside them,
 * some are clipped by the viewport, one has its corners reversed. */
#include "scene.h"
#include <GL/glu.h>

static void lit_objects(void)
{
    GLUquadric *q = gluNewQuadric();
    const GLfloat pos[4] = {2.0f, 3.0f, 4.0f, 1.0f};
    const GLfloat diffuse[4] = {0.9f, 0.6f, 0.3f, 1.0f};
    const GLfloat specular[4] = {1, 1, 1, 1};
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, 200.0 / 150.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 1, 6, 0, 0, 0, 0, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    gluSphere(q, 1.2, 28, 18);
    glTranslatef(1.6f, -0.4f, 0.8f);
    gluCylinder(q, 0.3, 0.3, 1.0, 16, 3);
    gluDeleteQuadric(q);
}

int main(int argc, char **argv)
{
    GLuint list;
    const GLfloat pos[4] = {100.0f, 40.0f, 60.0f, 1.0f};
    const GLdouble d1[2] = {150.5, 100.25}, d2[2] = {190.75, 140.0};
    const GLfloat f1[2] = {-10.0f, 120.0f}, f2[2] = {30.0f, 160.0f};
    const GLint i1[2] = {60, 2}, i2[2] = {90, 30};
    const GLshort s1[2] = {185, 5}, s2[2] = {215, 25};
    scene_begin(argc, argv, 200, 150);
    lit_objects();

    /* The overlay: pixel projection, lit by a light near the panel. */
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 200, 0, 150, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glNormal3f(0, 0, 1);

    glShadeModel(GL_FLAT);
    glRectf(4.0f, 4.0f, 50.0f, 40.0f);
    glRecti(60, 2, 90, 30);
    glRectiv(i1, i2);                      /* the same again, on top */
    glShadeModel(GL_SMOOTH);
    glRectd(100.25, 4.5, 140.75, 44.0);
    glRectdv(d1, d2);
    glRectsv(s1, s2);                      /* past the right edge */
    glRectfv(f1, f2);                      /* past the left edge */

    /* A display list: rectangles beside a glBegin/glEnd quad, both shadings. */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glShadeModel(GL_FLAT);
    glRects(40, 60, 70, 90);
    glBegin(GL_QUADS);
    glVertex2f(75, 60); glVertex2f(95, 60); glVertex2f(95, 80); glVertex2f(75, 80);
    glEnd();
    glRectf(100, 60, 130, 95);
    glShadeModel(GL_SMOOTH);
    glRectf(135, 60, 170, 95);
    glEndList();
    glCallList(list);

    /* Unlit, with the corners reversed and culling on: still front-facing. */
    glDisable(GL_LIGHTING);
    glEnable(GL_CULL_FACE);
    glColor3f(0.2f, 0.8f, 0.4f);
    glRectf(70.0f, 140.0f, 40.0f, 110.0f);
    glDisable(GL_CULL_FACE);
    glDeleteLists(list, 1);
    return scene_end();
}
