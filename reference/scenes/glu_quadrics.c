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

    glColor3ub(230, 50, 50);
    gluSphere(q, 1.2, 24, 16);

    glPushMatrix();
    glRotatef(-90.0f, 1, 0, 0);
    glTranslatef(1.0f, -1.2f, -1.5f);   /* world (1, -1.5, 1.2): in front of the disk */
    glColor3ub(50, 205, 80);
    gluCylinder(q, 0.5, 0.2, 3.0, 20, 4);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.0f, 0.0f, 0.3f);
    glColor3ub(60, 100, 240);
    gluDisk(q, 0.6, 2.0, 32, 3);
    glColor3ub(240, 230, 50);
    glTranslatef(0.0f, 0.0f, 0.4f);
    gluPartialDisk(q, 0.3, 1.6, 24, 2, 30.0, 135.0);
    glPopMatrix();

    gluDeleteQuadric(q);
    return scene_end();
}
