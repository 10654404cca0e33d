/* Clipping at the left and right planes: smooth triangles/quads reaching far
 * past x = 0 and x = width (colours must interpolate as if unclipped). */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-300.0f, 10.0f);   /* far left */
    glColor3f(0, 1, 0); glVertex2f(60.0f, 4.0f);
    glColor3f(0, 0, 1); glVertex2f(40.5f, 50.0f);
    glColor3f(1, 1, 0); glVertex2f(90.0f, 20.0f);     /* far right */
    glColor3f(0, 1, 1); glVertex2f(700.0f, 30.0f);
    glColor3f(1, 0, 1); glVertex2f(100.0f, 60.0f);
    glColor3f(1, 1, 1); glVertex2f(-20.0f, 70.0f);    /* spans both sides */
    glColor3f(1, 0, 0); glVertex2f(150.0f, 80.25f);
    glColor3f(0, 0, 1); glVertex2f(-10.0f, 100.0f);
    glEnd();
    glBegin(GL_QUADS);                                /* exactly on the edges */
    glColor3f(1, 0.5f, 0); glVertex2f(0.0f, 104.0f);
    glColor3f(0, 0.5f, 1); glVertex2f(128.0f, 104.0f);
    glColor3f(0.5f, 1, 0); glVertex2f(128.0f, 112.0f);
    glColor3f(1, 1, 1);    glVertex2f(0.0f, 112.0f);
    glColor3f(0.2f, 0.4f, 0.9f); glVertex2f(-1000.0f, 116.0f);
    glColor3f(0.9f, 0.1f, 0.3f); glVertex2f(1000.0f, 116.0f);
    glColor3f(0.1f, 0.9f, 0.3f); glVertex2f(1000.0f, 126.0f);
    glColor3f(0.9f, 0.9f, 0.1f); glVertex2f(-1000.0f, 126.0f);
    glEnd();
    return scene_end();
}
