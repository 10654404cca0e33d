/* size_common.h - a size-independent pattern (unit square mapped to the
 * whole buffer) for the size_* scenes. */
#ifndef SIZE_COMMON_H
#define SIZE_COMMON_H
#include "scene.h"

static inline void size_draw(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex3f(0.45f, 0.55f, 0.2f);
    glColor3f(1, 0, 0); glVertex3f(0.02f, 0.03f, 0.0f);
    glColor3f(0, 1, 0); glVertex3f(0.97f, 0.1f, -0.5f);
    glColor3f(0, 0, 1); glVertex3f(0.9f, 0.98f, 0.5f);
    glColor3f(1, 1, 0); glVertex3f(0.05f, 0.9f, -0.2f);
    glEnd();
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    glColor3f(0, 1, 1); glVertex3f(0.3f, 0.2f, 0.4f);
    glColor3f(0, 1, 1); glVertex3f(0.8f, 0.4f, 0.1f);
    glColor3f(1, 0, 1); glVertex3f(0.5f, 0.8f, 0.4f);
    glEnd();
}
#endif
