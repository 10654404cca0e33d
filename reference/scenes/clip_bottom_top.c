/* Clipping at the bottom and top planes: smooth geometry reaching far past
 * y = 0 and y = height. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(10.0f, -400.0f);   /* far below */
    glColor3f(0, 1, 0); glVertex2f(4.0f, 60.0f);
    glColor3f(0, 0, 1); glVertex2f(50.0f, 40.5f);
    glColor3f(1, 1, 0); glVertex2f(20.0f, 90.0f);     /* far above */
    glColor3f(0, 1, 1); glVertex2f(30.0f, 600.0f);
    glColor3f(1, 0, 1); glVertex2f(60.0f, 100.0f);
    glColor3f(1, 1, 1); glVertex2f(70.0f, -20.0f);    /* spans both */
    glColor3f(1, 0, 0); glVertex2f(80.25f, 150.0f);
    glColor3f(0, 0, 1); glVertex2f(100.0f, -10.0f);
    glEnd();
    glBegin(GL_QUAD_STRIP);                           /* huge vertical band */
    glColor3f(0.2f, 0.4f, 0.9f); glVertex2f(106.0f, -5000.0f);
    glColor3f(0.9f, 0.1f, 0.3f); glVertex2f(126.0f, -5000.0f);
    glColor3f(0.1f, 0.9f, 0.3f); glVertex2f(106.0f, 5000.0f);
    glColor3f(0.9f, 0.9f, 0.1f); glVertex2f(126.0f, 5000.0f);
    glEnd();
    return scene_end();
}
