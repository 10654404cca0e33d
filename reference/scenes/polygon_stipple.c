/* Polygon stipple: a pattern that shows its anchoring (the window's
 * bottom-left, not the viewport's), on lit and smooth polygons in a viewport
 * away from the origin, over a depth-tested background; the buffer is not a
 * multiple of 32 high, so an anchoring at the top would show. */
#include <GL/glu.h>

#include "scene.h"

static GLubyte pattern[128];

static void make_pattern(void)
{
    int row, col;
    for (row = 0; row < 32; row++)
        for (col = 0; col < 32; col++) {
            /* a diagonal band, a solid bottom row pair and a left column
             * pair: the corner they meet at is the pattern's origin */
            int on = ((col + row) % 8 < 3) || row < 2 || col < 2 || (row == 17 && col > 20);
            if (on) pattern[row * 4 + col / 8] |= (GLubyte)(0x80 >> (col % 8));
        }
}

int main(int argc, char **argv)
{
    static const float light[4] = {0.4f, 0.7f, 1.0f, 0};
    scene_options o = {150, 118, OSMESA_RGBA, 24, 1, 0};
    GLUquadric *q;
    scene_begin_ext(argc, argv, &o);
    make_pattern();
    glPolygonStipple(pattern);

    /* unstippled background, depth tested */
    glViewport(0, 0, 150, 118);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 150, 0, 118, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_QUADS);
    glColor3f(0.2f, 0.6f, 0.3f);
    glVertex3f(0, 0, 0.5f);
    glVertex3f(150, 0, 0.5f);
    glColor3f(0.6f, 0.2f, 0.5f);
    glVertex3f(150, 40, -0.5f);
    glVertex3f(0, 40, -0.5f);
    glEnd();

    /* stippled smooth quads and a polygon, over and under the background */
    glEnable(GL_POLYGON_STIPPLE);
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(5, 5, 0);
    glColor3f(0, 1, 0); glVertex3f(70, 10, 0);
    glColor3f(0, 0, 1); glVertex3f(66, 60, 0);
    glColor3f(1, 1, 0); glVertex3f(8, 52, 0);
    glEnd();
    glBegin(GL_POLYGON);
    glColor3f(1, 1, 1); glVertex2f(80, 4);
    glColor3f(0, 1, 1); glVertex2f(140, 12);
    glColor3f(1, 0, 1); glVertex2f(146, 50);
    glColor3f(1, 0.5f, 0); glVertex2f(110, 70);
    glColor3f(0.3f, 0.3f, 1); glVertex2f(78, 44);
    glEnd();

    /* a lit sphere in a viewport away from the origin */
    glViewport(37, 45, 70, 70);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 2, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -4);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.9f, 0.8f, 0.3f);
    q = gluNewQuadric();
    gluSphere(q, 1.4, 24, 16);
    gluDeleteQuadric(q);

    /* the same pattern changed, then stipple off again */
    glDisable(GL_LIGHTING);
    glViewport(0, 0, 150, 118);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 150, 0, 118, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    pattern[40] ^= 0xff;
    glPolygonStipple(pattern);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.9f, 0.9f);
    glVertex2f(2, 70); glVertex2f(34, 72); glVertex2f(10, 116);
    glEnd();
    /* stippled GL_LINE faces around a filled back face: Mesa's stipple
     * shader, bound by the filled one, stipples the outlines of the draw
     * (MESA_FACTS "Polygons") */
    glPolygonMode(GL_FRONT, GL_LINE);
    glBegin(GL_QUADS);
    glColor3f(1, 0.6f, 0.2f);
    glVertex2f(40, 75); glVertex2f(60, 75); glVertex2f(60, 95); glVertex2f(40, 95);
    glColor3f(0.2f, 0.9f, 1);
    glVertex2f(62, 75); glVertex2f(62, 110); glVertex2f(100, 110); glVertex2f(100, 75);
    glColor3f(1, 0.6f, 0.2f);
    glVertex2f(40, 97); glVertex2f(60, 97); glVertex2f(60, 116); glVertex2f(40, 116);
    glEnd();
    glPolygonMode(GL_FRONT, GL_FILL);
    glDisable(GL_POLYGON_STIPPLE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.5f, 0.5f, 0.9f);
    glVertex2f(112, 80); glVertex2f(148, 82); glVertex2f(140, 116);
    glEnd();
    return scene_end();
}
