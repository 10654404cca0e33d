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
    glColor3f(1, 0, 0); glVertex3f(-3.0f, -1.2f, 0.5f);    /* behind the eye */
    glColor3f(0, 1, 0); glVertex3f(5.0f, -3.0f, -9.0f);    /* past far, right, below */
    glColor3f(0, 0, 1); glVertex3f(-0.2f, 2.0f, -3.0f);    /* above the top */
    glEnd();
    glBegin(GL_QUADS);
    glColor3f(1, 1, 0); glVertex3f(-0.9f, 0.5f, -0.2f);
    glColor3f(0, 1, 1); glVertex3f(4.0f, 1.2f, -8.0f);
    glColor3f(1, 0, 1); glVertex3f(3.0f, -0.6f, -5.0f);
    glColor3f(1, 1, 1); glVertex3f(-0.6f, -0.3f, -0.2f);
    glEnd();
    return scene_end();
}
