/* format_common.h - an asymmetric pattern with varying alpha for the
 * format_* scenes (shows channel order, row order and row length). */
#ifndef FORMAT_COMMON_H
#define FORMAT_COMMON_H
#include "scene.h"

static inline void format_draw(void)
{
    const float w = (float)scene_width(), h = (float)scene_height();
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);   /* big smooth triangle, alpha 0 .. 1 */
    glColor4f(1, 0, 0, 0.0f);  glVertex3f(0.05f * w, 0.05f * h, 0.5f);
    glColor4f(0, 1, 0, 0.5f);  glVertex3f(0.95f * w, 0.10f * h, 0.0f);
    glColor4f(0, 0, 1, 1.0f);  glVertex3f(0.30f * w, 0.90f * h, -0.5f);
    glEnd();
    glBegin(GL_QUADS);       /* marker in the top-left corner (GL window coords) */
    glColor4f(1, 1, 1, 0.25f); glVertex2f(1, h - 1);
    glColor4f(1, 1, 0, 0.75f); glVertex2f(1, h - 9);
    glColor4f(1, 0, 1, 0.75f); glVertex2f(13, h - 9);
    glColor4f(0, 1, 1, 0.25f); glVertex2f(13, h - 1);
    glEnd();
    glBegin(GL_TRIANGLES);   /* flat marker bottom-right, distinct channel values */
    glColor4ub(10, 100, 200, 150); glVertex2f(w - 1, 1);
    glColor4ub(10, 100, 200, 150); glVertex2f(w - 1, 12);
    glColor4ub(10, 100, 200, 150); glVertex2f(w - 12, 1);
    glEnd();
}

static inline int format_scene(int argc, char **argv, GLenum format, int w, int h, int y_up,
                               int row_length)
{
    scene_options o;
    o.width = w;
    o.height = h;
    o.format = format;
    o.depth_bits = 24;
    o.y_up = y_up;
    o.row_length = row_length;
    /* a format the implementation refuses is compared as "refused" */
    if (scene_begin_try(argc, argv, &o) == 0) {
        format_draw();
        scene_readpixels_check();
    }
    return scene_end();
}
#endif
