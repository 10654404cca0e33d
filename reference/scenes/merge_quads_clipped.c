/* Separate glBegin/glEnd pairs of smooth GL_QUADS with no state change between
 * them, one of them partly outside the view volume: Mesa draws them as one
 * draw, so the clipped one decides how every quad of it is split. Then pairs
 * of GL_TRIANGLES with glColor between them (the colour becomes per-vertex
 * data while vertices are buffered) and 0.5-tie colours in perspective. */
#include "scene.h"

static void quad(float x, float y, float s, const float c[4][3])
{
    glBegin(GL_QUADS);
    glColor3fv(c[0]); glVertex2f(x, y);
    glColor3fv(c[1]); glVertex2f(x + s, y);
    glColor3fv(c[2]); glVertex2f(x + s, y + s);
    glColor3fv(c[3]); glVertex2f(x, y + s);
    glEnd();
}

int main(int argc, char **argv)
{
    static const float c[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};
    int i;
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    quad(4, 4, 28, c);
    quad(40, 4, 28, c);
    quad(110, 4, 30, c);          /* crosses the right edge: clipped */
    quad(4, 40, 28, c);
    glTranslatef(0, 0, 0);        /* a state change: the next draw starts anew */
    quad(40, 40, 28, c);
    quad(76, 40, 28, c);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (i = 0; i < 4; i++) {
        float x = -1.5f + i * 0.8f;
        glColor3f(0.5f, 0.3f, 0.1f + 0.2f * i);  /* set outside, vertices buffered after the first */
        glBegin(GL_TRIANGLES);
        glVertex3f(x, -0.2f, -1.5f);
        glVertex3f(x + 0.7f, -0.2f, -4.0f);
        glVertex3f(x + 0.2f, 0.9f, -2.5f);
        glEnd();
    }
    return scene_end();
}
