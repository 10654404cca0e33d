/* GLU on Mesa: gluPerspective + gluLookAt and gluSphere / gluCylinder /
 * gluDisk / gluPartialDisk intersecting each other (depth tested). */
#include "scene.h"
#include <GL/glu.h>

int main(int argc, char **argv)
{
    GLUquadric *q;
    scene_begin(argc, argv, 192, 144);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, 192.0 / 144.0, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(3.0, 2.5, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glEnable(GL_DEPTH_TEST);
    q = gluNewQuadric();
    gluQuadricNormals(q, GLU_NONE);

    glColor3f(0.9f, 0.2f, 0.2f);
    gluSphere(q, 1.2, 24, 16);

    glPushMatrix();
    glRotatef(-90.0f, 1, 0, 0);
    glTranslatef(0.8f, 0.0f, -1.5f);
    glColor3f(0.2f, 0.8f, 0.3f);
    gluCylinder(q, 0.5, 0.2, 3.0, 20, 4);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.0f, 0.0f, 0.3f);
    glColor3f(0.2f, 0.4f, 0.95f);
    gluDisk(q, 0.6, 2.0, 32, 3);
    glColor3f(0.95f, 0.9f, 0.2f);
    glTranslatef(0.0f, 0.0f, 0.4f);
    gluPartialDisk(q, 0.3, 1.6, 24, 2, 30.0, 135.0);
    glPopMatrix();

    gluDeleteQuadric(q);
    return scene_end();
}
