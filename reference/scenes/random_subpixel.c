/* 6000 tiny random triangles (< 1.5 px, many smaller than a pixel) with
 * smooth colours and random depth: sample-point coverage and small-triangle
 * edge cases. */
#include "scene.h"

int main(int argc, char **argv)
{
    int i, v;
    scene_begin(argc, argv, 64, 64);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    scene_srand(777u);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6000; i++) {
        float cx = scene_randf(0.0f, 64.0f), cy = scene_randf(0.0f, 64.0f);
        float size = scene_randf(0.05f, 1.5f);
        for (v = 0; v < 3; v++) {
            glColor3f(scene_randf(0.1f, 1), scene_randf(0.1f, 1), scene_randf(0.1f, 1));
            glVertex3f(cx + scene_randf(-size, size), cy + scene_randf(-size, size),
                       scene_randf(-1.0f, 1.0f));
        }
    }
    glEnd();
    return scene_end();
}
