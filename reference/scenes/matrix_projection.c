/* Projection stack and helpers: off-axis glFrustum, asymmetric glOrtho,
 * glPushMatrix/glPopMatrix on GL_PROJECTION, glRotatef about a
 * non-normalised axis, negative glScalef. */
#include "scene.h"

static void cube_faces(void)
{
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(-1, -1, 1); glVertex3f(1, -1, 1);
    glColor3f(1, 1, 0); glVertex3f(1, 1, 1); glVertex3f(-1, 1, 1);
    glColor3f(0, 1, 0); glVertex3f(1, -1, -1); glVertex3f(1, 1, -1);
    glColor3f(0, 1, 1); glVertex3f(1, 1, 1); glVertex3f(1, -1, 1);
    glColor3f(0, 0, 1); glVertex3f(-1, 1, -1); glVertex3f(1, 1, -1);
    glColor3f(1, 0, 1); glVertex3f(1, 1, 1); glVertex3f(-1, 1, 1);
    glColor3f(1, 1, 1); glVertex3f(-1, -1, -1); glVertex3f(-1, 1, -1);
    glColor3f(0.5f, 0.5f, 0.5f); glVertex3f(-1, 1, 1); glVertex3f(-1, -1, 1);
    glColor3f(1, 0.5f, 0); glVertex3f(-1, -1, -1); glVertex3f(1, -1, -1);
    glColor3f(0, 0.5f, 1); glVertex3f(1, -1, 1); glVertex3f(-1, -1, 1);
    glColor3f(0.5f, 1, 0); glVertex3f(-1, -1, -1); glVertex3f(-1, 1, -1);
    glColor3f(1, 0, 0.5f); glVertex3f(1, 1, -1); glVertex3f(1, -1, -1);
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 200, 120);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.3, 0.7, -0.3, 0.3, 1.0, 10.0);   /* off-axis */
    glPushMatrix();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(-0.6f, 0.0f, -5.0f);
    glRotatef(35.0f, 1.0f, 2.0f, 3.0f);            /* axis not normalised */
    cube_faces();

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-7.0, 3.0, -2.5, 3.5, -10.0, 4.0);     /* asymmetric ortho */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(1.5f, 0.5f, 0.0f);
    glRotated(-50.0, 0.3, -1.0, 0.2);
    glScalef(0.9f, -0.9f, 0.9f);                   /* negative scale */
    cube_faces();

    glMatrixMode(GL_PROJECTION);
    glPopMatrix();                                 /* back to the frustum */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(-1.4f, -0.9f, -4.0f);
    glScalef(0.25f, 0.25f, 0.25f);
    glRotatef(60.0f, 0.0f, 1.0f, 0.0f);
    cube_faces();
    return scene_end();
}
