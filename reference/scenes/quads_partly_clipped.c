/* Smooth GL_QUADS of which one needs clipping, and which of the others Mesa
 * draws in the same draw (a draw with a clipped vertex splits every quad
 * (0,1,3)(1,2,3), otherwise (0,1,2)(0,2,3); the quads are concave darts so
 * the split shows in the coverage too):
 *   - one glBegin whose first glColor comes after the clipped quad: Mesa's vbo
 *     grows its vertex format there and draws the quads before it as a draw
 *     of their own, so the inside quad after it is not split as clipped;
 *     the clipped quad crosses x = w, z = -w, or has a vertex with w < 0;
 *   - the same with the colour already per-vertex data: one draw;
 *   - glPushMatrix/glPopMatrix (top unchanged) and glMaterial between two
 *     glBegin/glEnd pairs: no format reset, the pairs stay one draw
 *     (glMaterial draws what is buffered, glPushMatrix does not). */
#include "scene.h"

static const float col[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};

/* A dart at (x, y), 40 x 16 pixels; colour per vertex when `colours`. */
static void inside(float x, float y, int colours)
{
    static const float v[4][2] = {{0, 0}, {40, 1}, {14, 5}, {3, 16}};
    int i;
    for (i = 0; i < 4; i++) {
        if (colours) glColor3fv(col[i]);
        glVertex2f(x + v[i][0], y + v[i][1]);
    }
}

/* A quad at (x, y) that needs clipping: kind 0 crosses the right edge, 1 has
 * a vertex beyond the near plane, 2 a vertex with w < 0. */
static void clipped(float x, float y, int kind)
{
    glVertex2f(x, y);
    if (kind == 0) glVertex2f(x + 60, y + 2);
    else glVertex2f(x + 30, y + 2);
    if (kind == 1) glVertex3f(x + 28, y + 14, 3.0f);
    else if (kind == 2) glVertex4f(-(x + 28) * 0.5f, -(y + 14) * 0.5f, 0, -0.5f);
    else glVertex2f(x + 58, y + 14);
    glVertex2f(x + 2, y + 12);
}

static void reset_format(void) { glTranslatef(0, 0, 0); } /* a state change: flush, fresh vbo format */

int main(int argc, char **argv)
{
    static const GLfloat diffuse[4] = {0.3f, 0.6f, 0.2f, 1};
    int k;
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glColor3f(0.8f, 0.6f, 0.4f);

    /* One glBegin: clipped quad without colour, then the colour: split off. */
    for (k = 0; k < 3; k++) {
        reset_format();
        glBegin(GL_QUADS);
        clipped(84, 4 + 20 * k, k);
        inside(4, 4 + 20 * k, 1);
        glEnd();
    }

    /* The same with the colour already per-vertex data: one draw. */
    reset_format();
    glBegin(GL_QUADS);
    glColor3f(0.8f, 0.6f, 0.4f);
    clipped(84, 64, 0);
    inside(4, 64, 1);
    glEnd();

    /* glPushMatrix/glPopMatrix between the pairs: one draw. */
    reset_format();
    glBegin(GL_QUADS);
    inside(4, 84, 1);
    glEnd();
    glPushMatrix();
    glPopMatrix();
    glBegin(GL_QUADS);
    clipped(84, 84, 0);
    glEnd();

    /* glMaterial between: the pairs are two draws, but the colour stays
     * per-vertex data, so the later glColor splits nothing off. */
    reset_format();
    glBegin(GL_QUADS);
    inside(4, 104, 1);
    glEnd();
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glBegin(GL_QUADS);
    clipped(84, 104, 0);
    inside(44, 104, 1);
    glEnd();
    return scene_end();
}
