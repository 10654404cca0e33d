/* A viewport four times the buffer size centred on it, then a 1x1 viewport. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 96, 96);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    glViewport(-144, -144, 384, 384);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex2f(0.0f, 0.0f);
    glColor3f(1, 0, 0); glVertex2f(0.3f, 0.0f);
    glColor3f(0, 1, 0); glVertex2f(0.0f, 0.3f);
    glColor3f(0, 0, 1); glVertex2f(-0.3f, 0.0f);
    glColor3f(1, 1, 0); glVertex2f(0.0f, -0.3f);
    glColor3f(1, 0, 0); glVertex2f(0.3f, 0.0f);
    glEnd();
    glViewport(5, 90, 1, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(0, 1, 1); glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(0, 1);
    glEnd();
    return scene_end();
}
