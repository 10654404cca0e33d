/* Like quads_partly_clipped, with glNormal instead of glColor (lighting off):
 * the first glNormal between glBegin and glEnd also grows Mesa's vbo vertex
 * format, so the whole quads before it are a draw of their own and decide
 * alone whether they need clipping (found by fuzz_random_state, seed 38):
 *   - an inside dart, glNormal, a clipped quad: the dart is not split as
 *     clipped;
 *   - a clipped quad, glNormal, an inside dart: the same the other way;
 *   - glNormal outside glBegin/glEnd with vertices buffered: the pending draw
 *     is drawn first. */
#include "scene.h"

/* A concave dart at (x, y), 40 x 16 pixels, so the split shows in coverage. */
static void inside(float x, float y)
{
    static const float v[4][2] = {{0, 0}, {40, 1}, {14, 5}, {3, 16}};
    int i;
    for (i = 0; i < 4; i++) glVertex2f(x + v[i][0], y + v[i][1]);
}

/* A quad at (x, y) crossing the right edge. */
static void clipped(float x, float y)
{
    glVertex2f(x, y);
    glVertex2f(x + 60, y + 2);
    glVertex2f(x + 58, y + 14);
    glVertex2f(x + 2, y + 12);
}

static void reset_format(void) { glTranslatef(0, 0, 0); } /* a state change: flush, fresh vbo format */

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glColor3f(0.8f, 0.6f, 0.4f);

    reset_format();
    glBegin(GL_QUADS);
    inside(4, 4);
    glNormal3f(0.2f, 0.3f, 0.9f);
    clipped(84, 4);
    glEnd();

    reset_format();
    glBegin(GL_QUADS);
    clipped(84, 24);
    glNormal3f(0.3f, 0.2f, 0.9f);
    inside(4, 24);
    glEnd();

    /* glNormal between two pairs with vertices buffered: two draws. */
    reset_format();
    glBegin(GL_QUADS);
    inside(4, 64);
    glEnd();
    glNormal3f(0.4f, 0.1f, 0.9f);
    glBegin(GL_QUADS);
    clipped(84, 64);
    glEnd();

    /* No glNormal: one draw, the dart split as clipped. */
    reset_format();
    glBegin(GL_QUADS);
    inside(4, 84);
    clipped(84, 84);
    glEnd();
    return scene_end();
}
