/* Mesa's immediate-mode vertex buffer (512 KiB) fills in the middle of long
 * glBegin/glEnd pairs: what is buffered is drawn and the primitive goes on in
 * the next draw. llvmpipe decides per draw (and per 4096-vertex segment)
 * whether to clip, which changes how smooth quads split, so the wrap points
 * show. Most quads are degenerate (drawing nothing) and only those around a
 * wrap are drawn, one per 8x8 cell; a clipped quad just before each wrap
 * makes its segment split quads the clipped way. Then a triangle strip and a
 * polygon that each cross a wrap, and a colour growing from 3 to 4 components
 * in the middle of a strip, a fan and a polygon. */
#include <math.h>

#include "scene.h"

#define CELL 8

/* v0 and v2 red, v1 and v3 black: the split diagonal shows. */
static void quad(int cell, float r3)
{
    float x = 100, y = 100, s = 0;
    if (cell >= 0) {
        x = (cell % 32) * CELL;
        y = (cell / 32) * CELL;
        s = CELL - 1;
    }
    glColor3f(1, r3, 0);
    glVertex2f(x, y);
    glColor3f(0, 0, r3);
    glVertex2f(x + s, y);
    glColor3f(1, r3, 0);
    glVertex2f(x + s, y + s);
    glColor3f(0, 0, r3);
    glVertex2f(x, y + s);
}

static void clipped_quad(void)
{
    glColor3f(1, 0, 0);
    glVertex2f(-10, -10);
    glColor3f(0, 0, 0);
    glVertex2f(20, -10);
    glColor3f(1, 0, 0);
    glVertex2f(20, 20);
    glColor3f(0, 0, 0);
    glVertex2f(-10, 20);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();

    /* Position 2 + colour 3 floats: 26213 vertices a buffer, so a wrap after
     * quad 6553 (one vertex copied over) and after quad 13106. */
    glBegin(GL_QUADS);
    for (int q = 0; q < 14000; q++) {
        int cell = -1;
        if (q >= 6300 && q < 6812) cell = q - 6300;          /* rows 0..15 */
        if (q >= 12900 && q < 13156) cell = 512 + q - 12900; /* rows 16..23 */
        if (q == 6500 || q == 13100)
            clipped_quad();
        else
            quad(cell, q > 13000 ? 0.5f : 0);
    }
    glEnd();
    glTranslatef(0, 0, 0); /* a flush: the format starts again */

    /* A long triangle strip across a wrap (copies 2 or 3 vertices), in the
     * band y 196..204; most of it folded onto one column. */
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 30000; i++) {
        float x = i < 26000 ? 2 : 2 + (i - 26000) * 0.06f;
        glColor3f((i % 7) / 6.0f, (i % 5) / 4.0f, 0.5f);
        glVertex2f(x, (i & 1) ? 204 : 196);
    }
    glEnd();

    /* A polygon across a wrap (copies its first and last vertex): a disc. */
    glBegin(GL_POLYGON);
    for (int i = 0; i < 30000; i++) {
        float a = 6.2831853f * i / 30000;
        glColor3f(0.5f + 0.5f * sinf(a * 3), 0.5f, 0.5f + 0.5f * cosf(a));
        glVertex2f(40 + 30 * cosf(a), 228 + 26 * sinf(a));
    }
    glEnd();
    glTranslatef(0, 0, 0);

    /* glColor4f after glColor3f inside a strip, a fan and a polygon: the
     * format grows, Mesa draws what it has and carries the primitive over;
     * the polygon's first vertex is outside, so its first piece is clipped. */
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < 9; i++) {
        if (i < 5)
            glColor3f(1, i / 8.0f, 0);
        else
            glColor4f(0, i / 8.0f, 1, 1);
        glVertex2f(90 + i * 8, (i & 1) ? 214 : 196);
    }
    glEnd();
    glTranslatef(0, 0, 0);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(200, 228);
    for (int i = 0; i < 8; i++) {
        float a = 0.7f * i;
        if (i < 4)
            glColor3f(1, 0.1f * i, 0);
        else
            glColor4f(0, 0.1f * i, 1, 1);
        glVertex2f(200 + 24 * cosf(a), 228 + 24 * sinf(a));
    }
    glEnd();
    glTranslatef(0, 0, 0);
    glBegin(GL_POLYGON);
    glColor3f(0, 1, 0);
    glVertex2f(150, 270);
    for (int i = 0; i < 6; i++) {
        if (i < 3)
            glColor3f(1, 0.2f * i, 0.3f);
        else
            glColor4f(0.2f * i, 0, 1, 1);
        glVertex2f(130 + 8 * i, 250 - 5 * (i % 2) - 3 * i);
    }
    glEnd();
    return scene_end();
}
