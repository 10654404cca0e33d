/* Fill rule with integer (pixel-corner) vertices: diagonals through pixel
 * centres, a fan around a pixel corner and a fan around a pixel centre,
 * half-pixel slivers and vertices at exact 1/256 sub-pixel offsets. */
#include "scene.h"

static int k;
static void colour(void)
{
    static const GLubyte pal[8][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0},
                                      {0, 255, 255}, {255, 0, 255}, {255, 128, 0}, {255, 255, 255}};
    glColor3ubv(pal[k++ % 8]);
}

static void fan(float cx, float cy, float r, int n)
{
    int i;
    static const float dirs[16][2] = {{1, 0}, {1, 0.5f}, {1, 1}, {0.5f, 1}, {0, 1}, {-0.5f, 1},
                                      {-1, 1}, {-1, 0.5f}, {-1, 0}, {-1, -0.5f}, {-1, -1},
                                      {-0.5f, -1}, {0, -1}, {0.5f, -1}, {1, -1}, {1, -0.5f}};
    for (i = 0; i < n; i++) {
        const float *a = dirs[i * 16 / n], *b = dirs[((i + 1) % n) * 16 / n];
        glVertex2f(cx, cy);
        glVertex2f(cx + a[0] * r, cy + a[1] * r);
        colour();
        glVertex2f(cx + b[0] * r, cy + b[1] * r);
    }
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 64, 64);
    scene_ortho_pixels();
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    /* square split along its diagonal, which passes through pixel centres */
    glVertex2f(2, 2); glVertex2f(14, 2); colour(); glVertex2f(14, 14);
    glVertex2f(2, 2); glVertex2f(14, 14); colour(); glVertex2f(2, 14);
    /* the other diagonal */
    glVertex2f(18, 2); glVertex2f(30, 2); colour(); glVertex2f(18, 14);
    glVertex2f(30, 2); glVertex2f(30, 14); colour(); glVertex2f(18, 14);
    fan(16.0f, 40.0f, 12.0f, 16);    /* around a pixel corner */
    fan(47.5f, 40.5f, 12.0f, 8);     /* around a pixel centre */
    /* half-pixel wide slivers */
    glVertex2f(34, 2); glVertex2f(34.5f, 2); colour(); glVertex2f(34.5f, 20);
    glVertex2f(36.25f, 2); glVertex2f(36.75f, 2); colour(); glVertex2f(36.75f, 20);
    /* edges 1/256 px either side of pixel centres */
    glVertex2f(40.0f, 2.5f + 1.0f / 256); glVertex2f(62.0f, 2.5f + 1.0f / 256); colour();
    glVertex2f(51.0f, 12.5f - 1.0f / 256);
    glVertex2f(40.0f, 14.5f - 1.0f / 256); glVertex2f(62.0f, 14.5f - 1.0f / 256); colour();
    glVertex2f(51.0f, 24.5f + 1.0f / 256);
    glEnd();
    return scene_end();
}
