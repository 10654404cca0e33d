/* Random lines: positions at random floats and on 1/512 grids, every mode,
 * widths from 1 to 9 (fractional too), flat and smooth, stippled or not,
 * GL_LINE_SMOOTH or not, some crossing the view's edges; in four panels so
 * that the four kinds do not cover one another. Stippled smooth lines make
 * pieces shorter than a pixel, which llvmpipe draws fainter. */
#include "scene.h"

static float coord(float lo, float hi)
{
    float v = scene_randf(lo, hi);
    switch (scene_rand() % 3) {
    case 0: return (float)(int)(v * 512.0f) / 512.0f;
    case 1: return (float)(int)v + 0.5f;
    default: return v;
    }
}

static void panel(int px, int py, int smooth, int stipple)
{
    static const GLenum modes[] = {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP};
    int k, i;
    glViewport(px, py, 128, 128);
    if (smooth) glEnable(GL_LINE_SMOOTH); else glDisable(GL_LINE_SMOOTH);
    if (stipple) glEnable(GL_LINE_STIPPLE); else glDisable(GL_LINE_STIPPLE);
    for (k = 0; k < 24; k++) {
        int n = 2 + (int)(scene_rand() % 5);
        glShadeModel(scene_rand() % 3 == 0 ? GL_FLAT : GL_SMOOTH);
        glLineWidth(scene_rand() % 2 ? 1.0f : scene_randf(1.0f, 9.0f));
        glLineStipple(1 + (int)(scene_rand() % 4), (GLushort)(scene_rand() & 0xffff));
        glBegin(modes[scene_rand() % 3]);
        for (i = 0; i < n; i++) {
            glColor4f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1), scene_randf(0.5f, 1));
            glVertex2f(coord(-10.0f, 138.0f), coord(-10.0f, 138.0f));
        }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 128, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    scene_srand(12345);
    panel(0, 0, 0, 0);
    panel(128, 0, 0, 1);
    panel(0, 128, 1, 0);
    panel(128, 128, 1, 1);
    return scene_end();
}
