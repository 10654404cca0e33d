/* GL_POINTS of sizes 1 to 64 (with .5 cases: 1.5 and 2.5 round down, 2.51
 * up), at pixel centres, corners, ties of the 1/256 snap and random
 * positions; wide points near the edges of a viewport smaller than the
 * buffer (a centre just inside spills past the viewport edge, one just
 * outside is dropped whole), near the buffer edges; sizes below 1, NaN and
 * 1e30, and points far outside the view. */
#include <math.h>

#include "scene.h"

static void point(float size, float x, float y, float r, float g, float b)
{
    glPointSize(size);
    glBegin(GL_POINTS);
    glColor3f(r, g, b);
    glVertex2f(x, y);
    glEnd();
}

int main(int argc, char **argv)
{
    static const float sizes[] = {1.0f, 1.5f, 2.0f, 2.5f, 2.51f, 3.0f, 3.49f, 3.5f, 4.0f, 4.5f, 5.0f,
                                  6.5f, 7.0f, 8.0f, 9.5f, 11.0f, 12.49f, 16.0f};
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    glEnable(GL_DEPTH_TEST); /* every point writes z = 0.5; the last, huge one goes behind */

    /* Rows of sizes at pixel centres, pixel corners and quarter offsets. */
    static const float offs[][2] = {{0.5f, 0.5f}, {0.0f, 0.0f}, {0.25f, 0.75f}, {0.5f, 0.0f},
                                    {0.0f, 0.5f}, {0.498046875f, 0.501953125f}};
    for (int r = 0; r < 6; ++r)
        for (int i = 0; i < 18; ++i)
            point(sizes[i], 8.0f + 13.0f * (float)i + offs[r][0], 232.0f - 20.0f * (float)r + offs[r][1],
                  0.1f + 0.05f * (float)i, 1.0f - 0.15f * (float)r, 0.5f);

    /* Random positions and sizes in the middle band. */
    scene_srand(3);
    for (int i = 0; i < 120; ++i)
        point(scene_randf(0.2f, 9.0f), scene_randf(8, 248), scene_randf(70, 110), scene_randf(0, 1),
              scene_randf(0, 1), scene_randf(0, 1));

    /* Big points: 24, 32.5, 33, 48, 64. */
    point(24.0f, 30.5f, 40.5f, 1, 0, 0);
    point(32.5f, 75.0f, 40.0f, 0, 1, 0);
    point(33.0f, 120.25f, 40.75f, 0, 0, 1);
    point(48.0f, 175.5f, 30.0f, 1, 1, 0);
    point(64.0f, 232.0f, 32.0f, 0, 1, 1); /* spills past the right edge of the buffer */

    /* Sizes below 1, NaN, huge: one pixel, one pixel, 255 pixels (drawn first, covered after). */
    point(0.3f, 4.5f, 60.5f, 1, 1, 1);
    point(NAN, 8.5f, 60.5f, 1, 1, 1);

    /* A viewport smaller than the buffer: centres just inside and just outside its edges. */
    glViewport(64, 120, 128, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 128.0, 0.0, 64.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    point(9.0f, 0.25f, 32.5f, 1, 0.5f, 0);    /* inside, spills left of the viewport */
    point(9.0f, -0.25f, 20.5f, 1, 0, 0);      /* outside: dropped */
    point(8.0f, 127.75f, 40.0f, 0, 0.5f, 1);  /* inside, spills right */
    point(8.0f, 128.25f, 20.0f, 1, 0, 0);     /* outside */
    point(11.0f, 64.5f, 63.9f, 0.5f, 1, 0.5f); /* inside, spills over the top */
    point(11.0f, 40.5f, 64.1f, 1, 0, 0);      /* outside */
    point(6.0f, 64.0f, 0.1f, 1, 1, 0.5f);     /* inside, spills below */
    point(6.0f, 80.0f, -0.1f, 1, 0, 0);       /* outside */
    point(5.0f, 1e30f, 1e30f, 1, 0, 0);       /* far outside */
    point(5.0f, -1e30f, 10.0f, 1, 0, 0);
    point(5.0f, NAN, 10.0f, 1, 0, 0);

    /* The full view again: a 1e30 point (clamped to 255) drawn behind by depth. */
    glViewport(0, 0, 256, 256);
    scene_ortho_pixels();
    glPointSize(1e30f);
    glBegin(GL_POINTS);
    glColor3f(0.2f, 0.2f, 0.25f);
    glVertex3f(128.0f, 128.0f, -0.999f);
    glEnd();
    return scene_end();
}
