/* Asking OSMesa for 32 depth bits (Mesa gives 24 in 32-bit words). */
#include "depth_common.h"

int main(int argc, char **argv)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, green[3] = {0, 1, 0},
                       blue[3] = {0, 0, 1};
    scene_options o = {64, 64, OSMESA_RGBA, 32, 1, 0};
    scene_begin_ext(argc, argv, &o);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    depth_quad(2, 2, 62, 40, 0.5f, -0.5f, red, yellow);
    depth_quad(2, 20, 62, 62, -0.5f, 0.5f, green, blue);
    return scene_end();
}
