/* 4000 deterministic random triangles (own LCG): smooth colours, random
 * depth, sizes from sub-pixel to large, depth tested with GL_LEQUAL. */
#include "scene.h"

int main(int argc, char **argv)
{
    int i, v;
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    scene_srand(20240601u);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 4000; i++) {
        float size = (i % 3 == 0) ? 1.2f : (i % 3 == 1) ? 10.0f : 60.0f;
        float cx = scene_randf(-20.0f, 276.0f), cy = scene_randf(-20.0f, 276.0f);
        for (v = 0; v < 3; v++) {
            glColor4f(scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1), scene_randf(0, 1));
            glVertex3f(cx + scene_randf(-size, size), cy + scene_randf(-size, size),
                       scene_randf(-1.0f, 1.0f));
        }
    }
    glEnd();
    return scene_end();
}
