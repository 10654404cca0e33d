/* No depth buffer (depth_bits 0): GL_DEPTH_TEST enabled behaves as disabled. */
#include "depth_common.h"

int main(int argc, char **argv)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, green[3] = {0, 1, 0},
                       blue[3] = {0, 0, 1};
    scene_options o = {96, 64, OSMESA_RGBA, 0, 1, 0};
    scene_begin_ext(argc, argv, &o);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER);
    depth_quad(4, 4, 80, 40, 0.5f, 0.5f, red, yellow);
    depth_quad(20, 20, 92, 60, -0.9f, 0.9f, green, blue);
    return scene_end();
}
