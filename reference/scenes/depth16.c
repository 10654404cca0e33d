/* 16-bit depth buffer: crossing slopes and nearly coplanar surfaces whose
 * separation is close to the 16-bit depth resolution. */
#include "depth_common.h"

int main(int argc, char **argv)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, green[3] = {0, 1, 0},
                       cyan[3] = {0, 1, 1}, blue[3] = {0, 0, 1}, white[3] = {1, 1, 1};
    scene_options o = {128, 128, OSMESA_RGBA, 16, 1, 0};
    int i;
    scene_begin_ext(argc, argv, &o);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    depth_quad(4, 4, 124, 60, 0.7f, -0.7f, red, yellow);
    depth_quad(4, 10, 124, 54, -0.7f, 0.7f, green, cyan);
    /* surfaces 2^-16 .. 8*2^-16 apart in window depth, alternately in front */
    for (i = 0; i < 8; i++) {
        float y = 66.0f + i * 7.0f;
        float dz = (float)(i + 1) * (2.0f / 65536.0f);
        depth_quad(4, y, 124, y + 6, 0.3f, -0.2f, blue, white);
        depth_quad(4, y, 124, y + 6, 0.3f + ((i & 1) ? dz : -dz), -0.2f - dz, yellow, red);
    }
    return scene_end();
}
