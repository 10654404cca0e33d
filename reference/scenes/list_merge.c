/* How a list's glBegin/glEnd pairs merge into draws, as Mesa's save module
 * merges them, where it decides pixels: llvmpipe splits every quad of a draw
 * one way when any vertex of the draw is outside the view volume. Each row is
 * one list of separate pairs with one clipped primitive among them:
 *   row 0: GL_QUADS pairs (merged, as in immediate mode);
 *   row 1: GL_QUADS pairs cut by a redundant glShadeModel (not compiled, so
 *          still one node) and by a glDepthFunc (compiled: a new node);
 *   row 2: GL_TRIANGLE_STRIPs (joined by degenerate triangles in a list,
 *          never in immediate mode) next to GL_QUADS;
 *   row 3: 3-vertex strips and fans (turned into GL_TRIANGLES) and triangles;
 *   row 4: a colour given in the second pair grows the vertex format;
 *   row 5: a list called between immediate-mode glBegin/glEnd pairs: the
 *          replay draws the pending pairs first, so the clipped pair after
 *          it does not change the split of the pairs before it.
 * Smooth colours everywhere, so the split shows. */
#include "scene.h"

static const float kColors[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};

static void quad(float x, float y, float s, int colors)
{
    glBegin(GL_QUADS);
    if (colors) glColor3fv(kColors[0]);
    glVertex2f(x, y);
    if (colors) glColor3fv(kColors[1]);
    glVertex2f(x + s, y);
    if (colors) glColor3fv(kColors[2]);
    glVertex2f(x + s, y + s);
    if (colors) glColor3fv(kColors[3]);
    glVertex2f(x, y + s);
    glEnd();
}

static void strip(float x, float y, float s)
{
    int i;
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 6; i++) {
        glColor3fv(kColors[i % 4]);
        glVertex2f(x + (i / 2) * s * 0.5f, y + (i % 2) * s);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 150);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);

    glNewList(1, GL_COMPILE);
    quad(4, 2, 12, 1);
    quad(40, 2, 12, 1);
    quad(152, 2, 14, 1);  /* clipped */
    quad(80, 2, 12, 1);
    glEndList();

    glNewList(2, GL_COMPILE);
    glShadeModel(GL_SMOOTH);
    quad(4, 26, 12, 1);
    glShadeModel(GL_SMOOTH);  /* repeats: not compiled, the node goes on */
    quad(152, 26, 14, 1);
    glDepthFunc(GL_LESS);     /* compiled even though it changes nothing: a new node */
    quad(40, 26, 12, 1);
    quad(80, 26, 12, 1);
    glEndList();

    glNewList(3, GL_COMPILE);
    strip(4, 50, 12);
    strip(150, 50, 14);  /* clipped */
    strip(40, 50, 12);
    quad(80, 50, 12, 1);
    quad(110, 50, 12, 1);
    glEndList();

    glNewList(4, GL_COMPILE);
    glBegin(GL_TRIANGLE_STRIP);
    glColor3fv(kColors[0]); glVertex2f(4, 74);
    glColor3fv(kColors[1]); glVertex2f(18, 74);
    glColor3fv(kColors[2]); glVertex2f(4, 88);
    glEnd();
    glBegin(GL_TRIANGLE_FAN);
    glColor3fv(kColors[3]); glVertex2f(154, 74);
    glColor3fv(kColors[1]); glVertex2f(168, 74);
    glColor3fv(kColors[2]); glVertex2f(154, 88);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3fv(kColors[2]); glVertex2f(40, 74);
    glColor3fv(kColors[0]); glVertex2f(54, 76);
    glColor3fv(kColors[3]); glVertex2f(44, 88);
    glEnd();
    quad(80, 74, 12, 1);
    glEndList();

    glNewList(5, GL_COMPILE);
    glColor3f(0.9f, 0.5f, 0.1f);
    quad(4, 98, 12, 0);    /* no colour in the node's format yet */
    quad(152, 98, 14, 0);  /* clipped */
    quad(40, 98, 12, 1);   /* the colour grows the format: a new node */
    quad(80, 98, 12, 1);
    quad(153, 110, 12, 1); /* clipped, in the new node */
    glEndList();

    glNewList(6, GL_COMPILE);
    quad(60, 122, 12, 1);
    quad(80, 122, 12, 1);
    glEndList();

    glCallList(1);
    glCallList(2);
    glCallList(3);
    glCallList(4);
    glCallList(5);
    /* Immediate pairs, the list, immediate pairs: is the pending draw cut? */
    quad(4, 122, 12, 1);
    quad(24, 122, 12, 1);
    glCallList(6);
    quad(120, 122, 12, 1);
    quad(152, 122, 14, 1);  /* clipped: decides the split of the pairs it merges with */
    glColor3f(0.2f, 0.8f, 0.8f);
    return scene_end();
}
