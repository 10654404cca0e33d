/* Perspective far-plane clipping: walls and a fan running past z_far. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);   /* left wall from z = -2 to z = -40 */
    glColor3f(1, 0, 0); glVertex3f(-1.0f, -1.0f, -2.0f);
    glColor3f(0, 1, 0); glVertex3f(-1.0f, -1.0f, -40.0f);
    glColor3f(0, 0, 1); glVertex3f(-1.0f, 1.0f, -40.0f);
    glColor3f(1, 1, 0); glVertex3f(-1.0f, 1.0f, -2.0f);
    glEnd();
    glBegin(GL_TRIANGLE_FAN);   /* slanted fan crossing z_far */
    glColor3f(1, 1, 1); glVertex3f(0.4f, 0.0f, -3.0f);
    glColor3f(1, 0, 1); glVertex3f(3.0f, -2.0f, -20.0f);
    glColor3f(0, 1, 1); glVertex3f(4.0f, 1.0f, -25.0f);
    glColor3f(1, 0.5f, 0); glVertex3f(1.0f, 3.0f, -14.0f);
    glColor3f(0.3f, 0.3f, 1); glVertex3f(0.0f, 1.5f, -8.0f);
    glEnd();
    glBegin(GL_TRIANGLES);   /* entirely beyond far: invisible */
    glColor3f(1, 1, 1); glVertex3f(-1, -1, -13); glVertex3f(1, -1, -13); glVertex3f(0, 1, -14);
    glEnd();
    return scene_end();
}
