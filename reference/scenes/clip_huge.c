/* Coordinates far outside the guard band (|x|,|y| up to 1e6 pixels) that
 * must still clip to the right shapes and colours. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-1.0e6f, -1.0e6f);
    glColor3f(0, 1, 0); glVertex2f(1.0e6f, -0.9e6f);
    glColor3f(0, 0, 1); glVertex2f(64.0f, 64.0f);
    glColor3f(1, 1, 0); glVertex2f(10.0f, 120.0f);
    glColor3f(0, 1, 1); glVertex2f(-2.0e5f, 121.5f);
    glColor3f(1, 0, 1); glVertex2f(3.0e5f, 100.0f);
    glEnd();
    return scene_end();
}
