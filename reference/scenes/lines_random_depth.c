/* Random lines under perspective with the depth test: every mode, widths 1
 * to 9, flat and smooth, stippled or not, GL_LINE_SMOOTH or not, some through
 * the near plane and the sides; one panel per kind. */
#include "scene.h"

static void panel(int px, int py, int smooth, int stipple)
{
    static const GLenum modes[] = {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP};
    int k, i;
    glViewport(px, py, 128, 128);
    if (smooth) glEnable(GL_LINE_SMOOTH); else glDisable(GL_LINE_SMOOTH);
    if (stipple) glEnable(GL_LINE_STIPPLE); else glDisable(GL_LINE_STIPPLE);
    for (k = 0; k < 20; k++) {
        int n = 2 + (int)(scene_rand() % 5);
        glShadeModel(scene_rand() % 3 == 0 ? GL_FLAT : GL_SMOOTH);
        glLineWidth(scene_rand() % 2 ? 1.0f : scene_randf(1.0f, 9.0f));
        glLineStipple(1 + (int)(scene_rand() % 4), (GLushort)(scene_rand() & 0xffff));
        glBegin(modes[scene_rand() % 3]);
        for (i = 0; i < n; i++) {
            glColor4f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1), scene_randf(0.5f, 1));
            glVertex3f(scene_randf(-2.5f, 2.5f), scene_randf(-2.5f, 2.5f), scene_randf(-8.0f, 0.5f));
        }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 256);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    scene_srand(4242);
    panel(0, 0, 0, 0);
    panel(128, 0, 0, 1);
    panel(0, 128, 1, 0);
    panel(128, 128, 1, 1);
    return scene_end();
}
