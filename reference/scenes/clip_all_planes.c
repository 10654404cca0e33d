/* One perspective triangle and one quad crossing all six clip planes at once. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 96);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.4, 0.4, -0.3, 0.3, 1.0, 6.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-9.0f, -6.0f, 0.5f);
    glColor3f(0, 1, 0); glVertex3f(9.0f, -5.0f, -9.0f);
    glColor3f(0, 0, 1); glVertex3f(0.5f, 9.0f, -3.0f);
    glEnd();
    glBegin(GL_QUADS);
    glColor3f(1, 1, 0); glVertex3f(-2.0f, 1.5f, -0.2f);
    glColor3f(0, 1, 1); glVertex3f(3.0f, 2.5f, -8.0f);
    glColor3f(1, 0, 1); glVertex3f(3.5f, -2.0f, -8.0f);
    glColor3f(1, 1, 1); glVertex3f(-2.0f, -1.0f, -0.2f);
    glEnd();
    return scene_end();
}
