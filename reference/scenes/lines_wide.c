/* Wide aliased lines: widths 1, 1.5, 2, 2.5, 3, 7 and 20 in strips and
 * loops, x-major and y-major, smooth and flat, with a line spilling past the
 * viewport (llvmpipe cuts lines at the buffer, not at the viewport). */
#include <math.h>

#include "scene.h"

static const float kWidths[] = {1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 7.0f, 20.0f};

int main(int argc, char **argv)
{
    int w, i;
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    for (w = 0; w < 7; w++) {
        float y = 12.0f + 26.0f * (float)w + (w & 1 ? 0.3f : 0.0f);
        glLineWidth(kWidths[w]);
        glShadeModel(w & 1 ? GL_FLAT : GL_SMOOTH);
        glBegin(GL_LINE_STRIP); /* a zig-zag: x-major, then steep */
        for (i = 0; i < 6; i++) {
            glColor3f((float)i / 5.0f, 1.0f - (float)w / 6.0f, 0.5f);
            glVertex2f(6.0f + 22.0f * (float)i + 0.25f * (float)w, y + ((i & 1) ? 9.6f : 0.0f));
        }
        glEnd();
        glBegin(GL_LINE_LOOP); /* a steep diamond */
        glColor3f(1, 0, 0); glVertex2f(160.0f + 10.0f * (float)w, y - 8.0f);
        glColor3f(0, 1, 0); glVertex2f(166.3f + 10.0f * (float)w, y + 2.0f);
        glColor3f(0, 0, 1); glVertex2f(160.0f + 10.0f * (float)w, y + 12.5f);
        glColor3f(1, 1, 1); glVertex2f(153.6f + 10.0f * (float)w, y + 2.0f);
        glEnd();
    }
    /* a wide line along the bottom of a smaller viewport spills below it */
    glViewport(140, 190, 100, 60);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 100, 0, 60, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLineWidth(9.0f);
    glBegin(GL_LINES);
    glColor3f(1, 1, 0); glVertex2f(5.0f, 0.5f); glColor3f(0, 1, 1); glVertex2f(95.0f, 2.5f);
    glColor3f(1, 0, 1); glVertex2f(0.5f, 10.0f); glColor3f(1, 1, 1); glVertex2f(1.5f, 55.0f);
    glEnd();
    return scene_end();
}
