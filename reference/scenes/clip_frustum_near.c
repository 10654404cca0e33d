/* Perspective (glFrustum) near-plane clipping, including vertices behind the
 * eye (w < 0) and a floor that runs from behind the viewer into the distance. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 120);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -0.75, 0.75, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);   /* floor from z = +10 (behind the eye) to z = -40 */
    glColor3f(1, 0, 0); glVertex3f(-4.0f, -1.0f, 10.0f);
    glColor3f(0, 1, 0); glVertex3f(4.0f, -1.0f, 10.0f);
    glColor3f(0, 0, 1); glVertex3f(4.0f, -1.0f, -40.0f);
    glColor3f(1, 1, 1); glVertex3f(-4.0f, -1.0f, -40.0f);
    glEnd();
    glBegin(GL_TRIANGLES);
    /* one vertex behind the eye, two in front */
    glColor3f(1, 1, 0); glVertex3f(-0.5f, 0.2f, 3.0f);
    glColor3f(0, 1, 1); glVertex3f(-3.0f, 0.5f, -6.0f);
    glColor3f(1, 0, 1); glVertex3f(-1.0f, 2.0f, -8.0f);
    /* two behind the eye, one in front */
    glColor3f(1, 0.5f, 0); glVertex3f(0.5f, 0.0f, 2.0f);
    glColor3f(0, 0.5f, 1); glVertex3f(1.5f, 1.0f, 0.5f);
    glColor3f(0.5f, 1, 0); glVertex3f(2.0f, 0.5f, -4.0f);
    /* straddles the near plane only (z = -1) */
    glColor3f(0.9f, 0.2f, 0.2f); glVertex3f(-0.6f, -0.4f, -0.5f);
    glColor3f(0.2f, 0.9f, 0.2f); glVertex3f(0.2f, -0.6f, -1.5f);
    glColor3f(0.2f, 0.2f, 0.9f); glVertex3f(0.1f, 0.3f, -2.0f);
    glEnd();
    return scene_end();
}
