/* Fill rule with vertices and edges exactly on pixel centres: adjacent flat
 * triangles in distinct colours show which one owns each shared pixel. */
#include "scene.h"

static int k;
static void colour(void)
{
    static const GLubyte pal[6][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255},
                                      {255, 255, 0}, {0, 255, 255}, {255, 0, 255}};
    glColor3ubv(pal[k++ % 6]);
}

int main(int argc, char **argv)
{
    int i, j;
    scene_begin(argc, argv, 64, 64);
    scene_ortho_pixels();
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLES);
    /* 4x4 grid of squares split into two triangles, corners on centres */
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++) {
            float x0 = 2.5f + i * 7, y0 = 2.5f + j * 7, x1 = x0 + 7, y1 = y0 + 7;
            glVertex2f(x0, y0); glVertex2f(x1, y0); colour(); glVertex2f(x1, y1);
            glVertex2f(x0, y0); glVertex2f(x1, y1); colour(); glVertex2f(x0, y1);
        }
    /* horizontal and vertical edges exactly through centres */
    glVertex2f(34.5f, 4.5f); glVertex2f(60.5f, 4.5f); colour(); glVertex2f(47.5f, 14.5f);
    glVertex2f(34.5f, 4.5f); glVertex2f(47.5f, 14.5f); colour(); glVertex2f(34.5f, 24.5f);
    glVertex2f(60.5f, 4.5f); glVertex2f(60.5f, 24.5f); colour(); glVertex2f(47.5f, 14.5f);
    glVertex2f(47.5f, 14.5f); glVertex2f(60.5f, 24.5f); colour(); glVertex2f(34.5f, 24.5f);
    /* triangles exactly one pixel wide/high along centres */
    glVertex2f(34.5f, 30.5f); glVertex2f(35.5f, 30.5f); colour(); glVertex2f(35.5f, 60.5f);
    glVertex2f(38.5f, 30.5f); glVertex2f(60.5f, 31.5f); colour(); glVertex2f(38.5f, 31.5f);
    /* degenerate triangles: must draw nothing */
    glVertex2f(40.5f, 40.5f); glVertex2f(50.5f, 50.5f); colour(); glVertex2f(45.5f, 45.5f);
    glVertex2f(40.5f, 52.5f); glVertex2f(40.5f, 52.5f); colour(); glVertex2f(40.5f, 52.5f);
    glEnd();
    return scene_end();
}
