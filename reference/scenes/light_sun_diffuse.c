/* The sun: one directional light (w = 0), diffuse only, on a finely tessellated smooth sphere (glOrtho). */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_ortho(1.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.95f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -1.0f, 1.0f, 1.5f, 0.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.5f, 0.3f, 1.0f);
    light_sphere(1.0f, 48, 24);
    return scene_end();
}
