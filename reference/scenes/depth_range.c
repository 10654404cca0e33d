/* Non-default glDepthRange: (0.25, 0.75), reversed (1, 0),
 * and the degenerate (0.5, 0.5), each in one column. */
#include "depth_common.h"

static void column(float x0)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, green[3] = {0, 1, 0},
                       blue[3] = {0, 0, 1}, white[3] = {1, 1, 1};
    depth_quad(x0 + 2, 8, x0 + 40, 120, 0.9f, -0.9f, red, yellow);
    depth_quad(x0 + 2, 30, x0 + 40, 100, -0.9f, 0.9f, green, blue);
    depth_quad(x0 + 14, 4, x0 + 28, 124, 0.1f, 0.1f, white, white);
}

int main(int argc, char **argv)
{
    depth_begin(argc, argv);
    glDepthRange(0.25, 0.75);
    column(0);
    glDepthRange(1.0, 0.0);   /* reversed: the farther surface wins with GL_LESS */
    column(42);
    glDepthFunc(GL_LEQUAL);
    glDepthRange(0.5, 0.5);
    column(84);
    return scene_end();
}
