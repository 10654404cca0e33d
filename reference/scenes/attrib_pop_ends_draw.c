/* glPushAttrib/glPopAttrib between glBegin/glEnd pairs of smooth GL_QUADS,
 * with nothing changed between push and pop. Each row starts with a quad
 * clipped at the right edge: the quads that share its draw are split the way
 * a clipped draw splits them, the others not. Mesa's glPopAttrib draws the
 * buffered vertices first whatever it restores (even an unchanged group, even
 * on underflow); glPushAttrib does not. One row per case. */
#include "scene.h"
#include "smooth_quad.h"

static const GLbitfield groups[] = {
    GL_DEPTH_BUFFER_BIT, GL_ALL_ATTRIB_BITS, GL_LIGHTING_BIT, GL_CURRENT_BIT, GL_ENABLE_BIT,
    GL_TRANSFORM_BIT, GL_VIEWPORT_BIT, GL_POLYGON_BIT, GL_HINT_BIT, GL_COLOR_BUFFER_BIT,
    GL_FOG_BIT, 0,
};
#define NGROUPS (int)(sizeof(groups) / sizeof(groups[0]))

/* 0 .. NGROUPS-1: push and pop; then push only (popped at the row's end);
 * then pop with an empty stack. */
static void op(int row)
{
    if (row < NGROUPS) {
        glPushAttrib(groups[row]);
        glPopAttrib();
    } else if (row < 2 * NGROUPS) {
        glPushAttrib(groups[row - NGROUPS]);
    } else {
        glPopAttrib();  /* GL_STACK_UNDERFLOW */
    }
}

int main(int argc, char **argv)
{
    int row, rows = 2 * NGROUPS + 1;
    scene_begin(argc, argv, 160, 4 + rows * 12);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    for (row = 0; row < rows; row++) {
        float y = 2 + row * 12;
        glTranslatef(0, 0, 0);  /* a real change: each row is a draw of its own */
        quad(155, y, 10);       /* crosses the right edge: clipped */
        op(row);
        quad(4, y, 10);
        op(row);
        quad(40, y, 10);
        quad(80, y, 10);
        if (row >= NGROUPS && row < 2 * NGROUPS) {
            glPopAttrib();
            glPopAttrib();
        }
    }
    glGetError();  /* the underflow row's error */
    return scene_end();
}
