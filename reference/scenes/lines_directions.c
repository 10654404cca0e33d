/* A star of 1-wide lines in every direction at sub-pixel offsets, drawn both
 * ways, to pin llvmpipe's end rules (diamond exit, x-major vs y-major, exact
 * half-pixel ends, zero-length lines). One short line per 16x16 cell. */
#include <math.h>

#include "scene.h"

static const float kOffsets[] = {0.0f, 0.5f, 0.25f, 0.75f, 0.125f, 0.375f, 0.0625f, 0.9375f,
                                 0.5f + 1.0f / 512.0f, 0.5f - 1.0f / 512.0f, 1.0f / 256.0f, 0.999f};

int main(int argc, char **argv)
{
    int cx, cy;
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    scene_srand(7);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_LINES);
    for (cy = 0; cy < 16; cy++) {
        for (cx = 0; cx < 16; cx++) {
            int k = cy * 16 + cx;
            float angle = (float)k * (6.2831853f / 64.0f) + (k >= 128 ? 0.01f * (float)(k & 7) : 0.0f);
            float len = (k & 1) ? 6.5f : 5.0f;
            float ox = kOffsets[k % 12], oy = kOffsets[(k / 12 + k) % 12];
            float x0 = 16.0f * cx + 8.0f + ox, y0 = 16.0f * cy + 8.0f + oy;
            float dx = len * cosf(angle), dy = len * sinf(angle);
            if (k % 5 == 4) { /* random sub-pixel ends */
                x0 += scene_randf(-0.5f, 0.5f);
                y0 += scene_randf(-0.5f, 0.5f);
            }
            glColor3f((float)cx / 15.0f, 0.3f, 1.0f - (float)cy / 15.0f);
            glVertex2f(x0 - dx, y0 - dy);
            glColor3f(1.0f, (float)cx / 15.0f, (float)cy / 15.0f);
            glVertex2f(x0 + dx, y0 + dy);
        }
    }
    glEnd();
    /* exact axis-aligned lines on pixel centres, edges and corners, both ways */
    glBegin(GL_LINES);
    glColor3f(1, 1, 1);
    glVertex2f(2.5f, 1.0f);  glVertex2f(10.5f, 1.0f);
    glVertex2f(20.5f, 1.5f); glVertex2f(12.5f, 1.5f);
    glVertex2f(1.0f, 2.5f);  glVertex2f(1.0f, 12.5f);
    glVertex2f(0.5f, 20.5f); glVertex2f(0.5f, 13.5f);
    glVertex2f(30.0f, 0.5f); glVertex2f(30.0f, 0.5f);  /* zero length */
    glEnd();
    return scene_end();
}
