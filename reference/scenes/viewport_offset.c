/* glViewport smaller than the buffer and offset from the origin; geometry
 * beyond NDC +-1 must be clipped to the viewport. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    glViewport(20, 30, 64, 50);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-1.5f, -1.2f);
    glColor3f(0, 1, 0); glVertex2f(1.3f, -1.0f);
    glColor3f(0, 0, 1); glVertex2f(0.0f, 1.8f);
    glEnd();
    glViewport(90, 4, 30, 110);
    glBegin(GL_QUADS);
    glColor3f(1, 1, 0); glVertex2f(-1, -1);
    glColor3f(0, 1, 1); glVertex2f(1, -1);
    glColor3f(1, 0, 1); glVertex2f(1, 1);
    glColor3f(1, 1, 1); glVertex2f(-1, 1);
    glEnd();
    glViewport(3, 100, 7, 5);   /* tiny viewport */
    glBegin(GL_QUADS);
    glColor3f(1, 0.5f, 0); glVertex2f(-2, -2); glVertex2f(2, -2); glVertex2f(2, 2); glVertex2f(-2, 2);
    glEnd();
    return scene_end();
}
