/* Perspective-interpolated depth: two intersecting slanted quads and a
 * tetrahedron-like fan seen through glFrustum. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.4, 0.4, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(-2.5f, -1.5f, 2.0f);
    glColor3f(1, 1, 0); glVertex3f(2.5f, -1.5f, -6.0f);
    glColor3f(1, 1, 1); glVertex3f(2.5f, 1.0f, -6.0f);
    glColor3f(1, 0, 1); glVertex3f(-2.5f, 1.0f, 2.0f);
    glColor3f(0, 1, 0); glVertex3f(-2.5f, -1.0f, -6.0f);
    glColor3f(0, 1, 1); glVertex3f(2.5f, -1.0f, 2.0f);
    glColor3f(0, 0, 1); glVertex3f(2.5f, 1.5f, 2.0f);
    glColor3f(0.5f, 0.5f, 0.5f); glVertex3f(-2.5f, 1.5f, -6.0f);
    glEnd();
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex3f(0.0f, 0.2f, 1.0f);
    glColor3f(1, 0, 0); glVertex3f(-1.0f, -0.8f, -1.0f);
    glColor3f(0, 1, 0); glVertex3f(1.0f, -0.8f, -1.0f);
    glColor3f(0, 0, 1); glVertex3f(0.0f, 1.2f, -1.5f);
    glColor3f(1, 0, 0); glVertex3f(-1.0f, -0.8f, -1.0f);
    glEnd();
    return scene_end();
}
