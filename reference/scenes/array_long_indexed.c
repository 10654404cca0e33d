/* A long indexed draw: 60,000 random small triangles (GL_TRIANGLES through
 * glDrawElements), back-face culling on, one vertex at the end far outside
 * the view, so the draw needs Mesa's clipping pipeline somewhere; and a long
 * indexed GL_QUADS draw. (How Mesa splits indexed draws is shown by the
 * indexed_* scenes.) */
#include "scene.h"

#define NT 60000
#define NV (NT * 3)

static float pos[NV][2], col[NV][4];
static GLuint idx[NV];

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 160, 160);
    scene_ortho_pixels();
    scene_srand(7);
    for (i = 0; i < NV; i++) {
        float x = scene_randf(0, 160), y = scene_randf(0, 160);
        if (i % 3) {
            x = pos[i - i % 3][0] + scene_randf(-3, 3);
            y = pos[i - i % 3][1] + scene_randf(-3, 3);
        }
        pos[i][0] = x;
        pos[i][1] = y;
        col[i][0] = scene_randf(0, 1);
        col[i][1] = scene_randf(0, 1);
        col[i][2] = scene_randf(0, 1);
        col[i][3] = 1;
        idx[i] = (GLuint)((i * 7919u) % NV); /* shuffled: long and short triangles */
    }
    pos[NV - 2][0] = 5000; /* outside */
    glEnable(GL_CULL_FACE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(4, GL_FLOAT, 0, col);
    glDrawElements(GL_TRIANGLES, NV, GL_UNSIGNED_INT, idx);
    glDisable(GL_CULL_FACE);
    glTranslatef(0, 0, 0);
    glDrawElements(GL_QUADS, 40000, GL_UNSIGNED_INT, idx + 1000);
    scene_readpixels_check();
    return scene_end();
}
