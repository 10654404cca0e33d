/* Long glDrawArrays (32,000 and 96,000 vertices): Mesa's draw module draws
 * them in segments of 4096 vertices and decides per segment whether it needs
 * clipping, which changes how each quad is split; libglfixed also fetches
 * such a draw in bounded chunks. GL_QUADS (a grid of 1-pixel quads),
 * GL_QUAD_STRIP and GL_TRIANGLE_STRIP (slivers), smooth colours from a colour
 * array, a few vertices pushed outside the view in some segments only. */
#include "scene.h"

#include <stdlib.h>

#define QUADS_X 160
#define QUADS_Y 50
#define NQ (QUADS_X * QUADS_Y * 4)
#define NS 96002

static float qpos[NQ][2], qcol[NQ][4];
static float spos[NS][2], scol[NS][4];

static void set_color(float *c, unsigned k)
{
    c[0] = (k * 37 % 256) / 255.0f;
    c[1] = (k * 91 % 256) / 255.0f;
    c[2] = (k * 53 % 256) / 255.0f;
    c[3] = 1.0f;
}

int main(int argc, char **argv)
{
    int x, y, k = 0, i;
    scene_begin(argc, argv, 160, 150);
    for (y = 0; y < QUADS_Y; y++)
        for (x = 0; x < QUADS_X; x++) {
            float x0 = x, y0 = y, x1 = x + 1.0f, y1 = y + 1.0f;
            float v[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            for (i = 0; i < 4; i++, k++) {
                qpos[k][0] = v[i][0];
                qpos[k][1] = v[i][1];
                set_color(qcol[k], k);
            }
        }
    /* push one quad of segments 1, 3 and 6 outside the view (x + 1000) */
    for (i = 0; i < 4; i++) {
        qpos[1 * 4096 + 100 + i][0] += 1000;
        qpos[3 * 4096 + 2000 + i][0] += 1000;
        qpos[6 * 4096 + 8 + i][0] += 1000;
    }
    for (k = 0; k < NS; k++) {
        spos[k][0] = 160.0f * (k / 2) / (NS / 2);
        spos[k][1] = (k % 2) ? 150.0f : 0.0f;
        set_color(scol[k], k * 7);
    }
    spos[5 * 4094 + 11][1] = -500.0f; /* outside, in one segment */
    spos[17 * 4094 + 4000][1] = 900.0f;

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 160, 0, 150, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    glViewport(0, 0, 160, 50);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 160, 0, 50, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glVertexPointer(2, GL_FLOAT, 0, qpos);
    glColorPointer(4, GL_FLOAT, 0, qcol);
    glDrawArrays(GL_QUADS, 0, NQ);

    glViewport(0, 50, 160, 50);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 160, 0, 150, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glVertexPointer(2, GL_FLOAT, 0, spos);
    glColorPointer(4, GL_FLOAT, 0, scol);
    glDrawArrays(GL_QUAD_STRIP, 0, NS);

    glViewport(0, 100, 160, 50);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, NS);
    scene_readpixels_check();
    return scene_end();
}
