/* Viewports partly outside the buffer (negative origin, past the right/top
 * edge, larger than the buffer): only the buffer part is drawn. */
#include "scene.h"

static void quad(float r, float g, float b)
{
    glBegin(GL_QUADS);
    glColor3f(r, g, b); glVertex2f(-0.9f, -0.9f);
    glColor3f(g, b, r); glVertex2f(0.9f, -0.8f);
    glColor3f(b, r, g); glVertex2f(0.8f, 0.9f);
    glColor3f(1, 1, 1); glVertex2f(-0.85f, 0.95f);
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 112);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    glViewport(-40, -30, 100, 80);    /* off the bottom-left corner */
    quad(1, 0, 0);
    glViewport(80, 70, 100, 90);      /* off the top-right corner */
    quad(0, 1, 0);
    glViewport(90, -50, 60, 100);     /* off the bottom-right */
    quad(0, 0, 1);
    glViewport(-300, 40, 400, 30);    /* much wider than the buffer */
    quad(1, 1, 0);
    return scene_end();
}
