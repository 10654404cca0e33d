/* GL_LINE_SMOOTH at widths 1, 2 and 3.5 (llvmpipe draws them through the draw
 * module's aaline stage): coverage lands in alpha; no blending, so the
 * written alpha is compared. Also smooth and stippled, flat, under
 * perspective with the depth test, and clipped. */
#include <math.h>

#include "scene.h"

static const float kWidths[] = {1.0f, 2.0f, 3.5f};

int main(int argc, char **argv)
{
    int w, i;
    scene_begin(argc, argv, 192, 192);
    scene_ortho_pixels();
    glEnable(GL_LINE_SMOOTH);
    for (w = 0; w < 3; w++) {
        glLineWidth(kWidths[w]);
        glBegin(GL_LINES);
        for (i = 0; i < 8; i++) {
            float a = 0.4f * (float)i + 0.1f;
            float cx = 32.0f + 64.0f * (float)w, cy = 40.0f;
            glColor4f(1, 0.5f, 0.25f * (float)(i & 3), 1);
            glVertex2f(cx + 6.0f * cosf(a), cy + 6.0f * sinf(a));
            glColor4f(0.2f, 1, 1, 0.8f);
            glVertex2f(cx + 28.0f * cosf(a), cy + 28.0f * sinf(a));
        }
        glEnd();
        glBegin(GL_LINE_STRIP);
        glColor4f(1, 1, 1, 1);
        glVertex2f(8.0f + 64.0f * (float)w, 90.5f);
        glVertex2f(56.0f + 64.0f * (float)w, 90.5f);
        glVertex2f(40.3f + 64.0f * (float)w, 120.2f);
        glEnd();
    }
    /* stippled and smooth, flat shaded */
    glShadeModel(GL_FLAT);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x3c3c);
    glLineWidth(2.5f);
    glBegin(GL_LINE_STRIP);
    glColor4f(1, 0, 0, 1); glVertex2f(4.0f, 130.5f);
    glColor4f(0, 1, 0, 0.6f); glVertex2f(90.0f, 140.0f);
    glColor4f(0, 0, 1, 1); glVertex2f(100.0f, 188.0f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glShadeModel(GL_SMOOTH);
    /* perspective, depth test, crossing the near plane and the right edge */
    glEnable(GL_DEPTH_TEST);
    glViewport(96, 128, 96, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.7, 0.7, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLineWidth(1.5f);
    glBegin(GL_LINES);
    for (i = 0; i < 6; i++) {
        float f = (float)i;
        glColor4f(1, 1, 0, 1); glVertex3f(-0.9f + 0.3f * f, -0.6f, -1.5f);
        glColor4f(0, 0.5f, 1, 1); glVertex3f(-0.2f + 0.4f * f, 0.6f, -6.0f);
        glColor4f(1, 0, 1, 1); glVertex3f(-1.5f, 0.5f - 0.15f * f, -3.0f);
        glColor4f(0, 1, 0, 1); glVertex3f(2.5f, -0.4f + 0.1f * f, -2.0f + 2.5f * f);
    }
    glEnd();
    return scene_end();
}
