/* Mesa hands the primitives buffered between two flushes to its draw module
 * in runs of one mode; a run other than the first whose first primitive is an
 * empty glBegin/glEnd draws nothing. Each row is one flush (a glTranslatef
 * between rows): quads, then an empty polygon and two polygons (not drawn);
 * the same without the quads (drawn); a polygon before the empty one (drawn);
 * an empty GL_QUADS that the next quads merge into (drawn); strips and quad
 * strips after an empty one of their kind (not drawn); a fan between (a new
 * run, drawn). */
#include "scene.h"

static float X, Y;

static void prim(GLenum mode, int n)
{
    const float x = X, y = Y;
    X += 24;
    glBegin(mode);
    for (int i = 0; i < n; i++) {
        glColor3f(0.2f + 0.15f * i, 1 - 0.15f * i, 0.5f);
        if (mode == GL_TRIANGLE_STRIP || mode == GL_QUAD_STRIP)
            glVertex2f(x + (i & 1) * 18, y + (i / 2) * 9);
        else if (mode == GL_QUADS)
            glVertex2f(x + ((i + 1) & 2) * 9, y + (i & 2) * 9);
        else
            glVertex2f(x + 9 + 9 * (i == 1 || i == 2) - 9 * (i == 4) - 0 * i, y + 4 * i);
    }
    glEnd();
}

static void row(void)
{
    glTranslatef(0, 0, 0); /* a flush: a new row starts a new set of runs */
    X = 4;
    Y += 24;
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 160);
    scene_ortho_pixels();
    Y = -20;
    row(); prim(GL_QUADS, 4); prim(GL_POLYGON, 0); prim(GL_POLYGON, 5); prim(GL_POLYGON, 5);
    row(); prim(GL_POLYGON, 0); prim(GL_POLYGON, 5); prim(GL_POLYGON, 5);
    row(); prim(GL_QUADS, 4); prim(GL_POLYGON, 5); prim(GL_POLYGON, 0); prim(GL_POLYGON, 5);
    row(); prim(GL_POLYGON, 5); prim(GL_QUADS, 0); prim(GL_QUADS, 4); prim(GL_QUADS, 4);
    row(); prim(GL_QUADS, 4); prim(GL_TRIANGLE_STRIP, 0); prim(GL_TRIANGLE_STRIP, 6); prim(GL_QUAD_STRIP, 0); prim(GL_QUAD_STRIP, 6);
    row(); prim(GL_QUADS, 4); prim(GL_POLYGON, 0); prim(GL_TRIANGLE_FAN, 5); prim(GL_POLYGON, 5);
    return scene_end();
}
