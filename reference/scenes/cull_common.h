/* cull_common.h - counter-clockwise (left column) and clockwise (right
 * column) triangles, quads, polygons and a strip whose triangles alternate
 * winding, for the cull_* scenes.  128x128 pixel space. */
#ifndef CULL_COMMON_H
#define CULL_COMMON_H
#include "scene.h"

static inline void cull_begin(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
}

static inline void cull_draw(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(4, 4);  glColor3f(0, 1, 0); glVertex2f(56, 6);   glColor3f(0, 0, 1); glVertex2f(20, 36);  /* CCW */
    glColor3f(1, 1, 0); glVertex2f(68, 4); glColor3f(0, 1, 1); glVertex2f(80, 36);  glColor3f(1, 0, 1); glVertex2f(124, 6); /* CW */
    glEnd();
    glBegin(GL_QUADS);
    glColor3f(1, 0.5f, 0); glVertex2f(4, 42);  glColor3f(0, 0.5f, 1); glVertex2f(56, 42);
    glColor3f(0.5f, 1, 0); glVertex2f(56, 70); glColor3f(1, 1, 1);    glVertex2f(4, 66);   /* CCW */
    glColor3f(1, 0.5f, 0); glVertex2f(68, 42); glColor3f(0, 0.5f, 1); glVertex2f(70, 70);
    glColor3f(0.5f, 1, 0); glVertex2f(124, 68); glColor3f(1, 1, 1);   glVertex2f(120, 44); /* CW */
    glEnd();
    glBegin(GL_POLYGON);   /* CCW pentagon */
    glColor3f(1, 0, 0); glVertex2f(30, 76); glColor3f(0, 1, 0); glVertex2f(54, 84);
    glColor3f(0, 0, 1); glVertex2f(48, 100); glColor3f(1, 1, 0); glVertex2f(14, 100);
    glColor3f(1, 0, 1); glVertex2f(6, 84);
    glEnd();
    glBegin(GL_POLYGON);   /* CW pentagon */
    glColor3f(1, 0, 0); glVertex2f(94, 76); glColor3f(0, 1, 0); glVertex2f(70, 84);
    glColor3f(0, 0, 1); glVertex2f(76, 100); glColor3f(1, 1, 0); glVertex2f(110, 100);
    glColor3f(1, 0, 1); glVertex2f(120, 84);
    glEnd();
    glBegin(GL_TRIANGLE_STRIP);   /* 6 triangles with a twist: they do not all face the same way */
    glColor3f(1, 0, 0); glVertex2f(4, 106);   glColor3f(0, 1, 0); glVertex2f(24, 124);
    glColor3f(0, 0, 1); glVertex2f(40, 108);  glColor3f(1, 1, 0); glVertex2f(56, 122);
    glColor3f(0, 1, 1); glVertex2f(88, 124);  glColor3f(1, 0, 1); glVertex2f(90, 104);
    glColor3f(1, 1, 1); glVertex2f(110, 124); glColor3f(1, 0.5f, 0); glVertex2f(124, 106);
    glEnd();
}
#endif
