/* Thousands of points at random sub-pixel positions (on the 1/256 grid, on
 * its half-steps and anywhere), random sizes 0.5 to 12 and random depths in
 * a perspective view, non-smooth and smooth, flat and smooth shading, depth
 * test on: the snap, the .5 rounding and the even-size centring wherever
 * they tie. */
#include "scene.h"

static float grid(float lo, float hi, int kind)
{
    float v = scene_randf(lo, hi);
    if (kind == 0) return (float)(int)(v * 256.0f) / 256.0f;
    if (kind == 1) return ((float)(int)(v * 256.0f) + 0.5f) / 256.0f;
    return v;
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 256);
    scene_srand(99);
    glEnable(GL_DEPTH_TEST);
    for (int pass = 0; pass < 2; ++pass) {
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        if (pass == 0)
            glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
        else
            glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        for (int k = 0; k < 40; ++k) {
            float size = (k % 4 == 0) ? (float)(1 + k % 9) + 0.5f : scene_randf(0.5f, 12.0f);
            glPointSize(size);
            glShadeModel((k & 1) ? GL_FLAT : GL_SMOOTH);
            if (k % 5 == 4)
                glEnable(GL_POINT_SMOOTH);
            else
                glDisable(GL_POINT_SMOOTH);
            glBegin(GL_POINTS);
            for (int i = 0; i < 40; ++i) {
                int kind = (int)(scene_rand() % 3);
                glColor4f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1), scene_randf(0.3f, 1.0f));
                if (pass == 0) {
                    glVertex3f(grid(0.0f, 256.0f, kind), grid(0.0f, 256.0f, kind), scene_randf(-0.9f, 0.9f));
                } else {
                    float z = scene_randf(-9.0f, -1.2f);
                    glVertex3f(scene_randf(-1.0f, 1.0f) * -z, scene_randf(-1.0f, 1.0f) * -z, z);
                }
            }
            glEnd();
        }
    }
    return scene_end();
}
