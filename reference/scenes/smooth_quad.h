/* One glBegin(GL_QUADS)/glEnd of a smooth quad with four colours, the shape
 * the immediate-mode merge scenes draw: llvmpipe's split of it (REFERENCE.md,
 * MESA_FACTS.md "Quads") shows whether it shared a draw with a clipped quad. */
#ifndef GLFX_SMOOTH_QUAD_H
#define GLFX_SMOOTH_QUAD_H

#include "scene.h"

static void quad(float x, float y, float s)
{
    static const float c[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0.2f}};
    glBegin(GL_QUADS);
    glColor3fv(c[0]); glVertex2f(x, y);
    glColor3fv(c[1]); glVertex2f(x + s, y);
    glColor3fv(c[2]); glVertex2f(x + s, y + s);
    glColor3fv(c[3]); glVertex2f(x, y + s);
    glEnd();
}

#endif
