/* GL_COMPILE_AND_EXECUTE: the list draws while it is compiled (Mesa feeds
 * the vertices back through immediate mode, so they split and merge as
 * immediate-mode vertices) and again, as a list, when called. Separate
 * GL_QUADS pairs with one clipped, state changes and a nested call. */
#include "scene.h"

static const float kColors[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};

static void quad(float x, float y, float s)
{
    int i;
    static const float dx[4] = {0, 1, 1, 0}, dy[4] = {0, 0, 1, 1};
    glBegin(GL_QUADS);
    for (i = 0; i < 4; i++) {
        glColor3fv(kColors[i]);
        glVertex2f(x + s * dx[i], y + s * dy[i]);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);

    glNewList(2, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.9f, 0.9f); glVertex2f(0, 0);
    glColor3f(0.9f, 0.2f, 0.9f); glVertex2f(14, 2);
    glColor3f(0.9f, 0.9f, 0.2f); glVertex2f(4, 13);
    glEnd();
    glEndList();

    glNewList(1, GL_COMPILE_AND_EXECUTE);
    quad(4, 4, 14);
    quad(40, 4, 14);
    quad(150, 4, 16);  /* clipped */
    quad(76, 4, 14);
    glTranslatef(0, 24, 0);
    quad(4, 4, 14);
    glShadeModel(GL_FLAT);
    quad(40, 4, 14);
    glShadeModel(GL_SMOOTH);
    glPushMatrix();
    glTranslatef(80, 2, 0);
    glCallList(2);
    glPopMatrix();
    quad(110, 4, 14);
    glEndList();

    glLoadIdentity();
    glTranslatef(2, 64, 0);
    glCallList(1);
    return scene_end();
}
