/* Nested display lists: a petal list, a flower list that calls it while
 * rotating, a bouquet that calls flowers with colour and matrix changes, and
 * a list that calls a list defined (and redefined) after it. */
#include <math.h>

#include "scene.h"

enum { PETAL = 1, FLOWER, BOUQUET, LATER, USES_LATER };

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 160, 160);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-8, 8, -8, 8, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glShadeModel(GL_SMOOTH);

    glNewList(PETAL, GL_COMPILE);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 0.3f);
    glVertex2f(0, 0);
    for (i = 0; i <= 6; i++) {
        const float a = -0.35f + 0.7f * i / 6;
        glColor3f(0.9f, 0.2f + 0.1f * i, 0.4f);
        glVertex2f(2.5f * cosf(a), 2.5f * sinf(a));
    }
    glEnd();
    glEndList();

    glNewList(FLOWER, GL_COMPILE);
    for (i = 0; i < 5; i++) {
        glCallList(PETAL);
        glRotatef(72, 0, 0, 1);
    }
    glBegin(GL_TRIANGLES);  /* a centre after the nested calls */
    glColor3f(0.3f, 0.2f, 0.1f);
    glVertex2f(-0.4f, -0.3f);
    glVertex2f(0.4f, -0.3f);
    glVertex2f(0, 0.45f);
    glEnd();
    glEndList();

    glNewList(BOUQUET, GL_COMPILE);
    glPushMatrix();
    glTranslatef(-4, -3.5f, 0);
    glCallList(FLOWER);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(3.7f, -3, 0);
    glScalef(0.8f, 0.8f, 1);
    glRotatef(17, 0, 0, 1);
    glCallList(FLOWER);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.3f, 3.6f, 0);
    glScalef(1.2f, 1.2f, 1);
    glCallList(FLOWER);
    glPopMatrix();
    glEndList();

    glNewList(USES_LATER, GL_COMPILE);
    glTranslatef(6.5f, 6.5f, 0);
    glCallList(LATER);  /* does not exist yet: resolved when executed */
    glEndList();
    glNewList(LATER, GL_COMPILE);
    glColor3f(0.2f, 0.6f, 1);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
    glEnd();
    glEndList();

    glCallList(BOUQUET);
    glPushMatrix();
    glCallList(USES_LATER);
    glPopMatrix();
    glNewList(LATER, GL_COMPILE);  /* redefined: the caller sees the new one */
    glBegin(GL_TRIANGLES);
    glColor3f(0.1f, 0.9f, 0.6f);
    glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(0, 1);
    glEnd();
    glEndList();
    glPushMatrix();
    glTranslatef(-13, 0, 0);
    glCallList(USES_LATER);
    glPopMatrix();
    return scene_end();
}
