/* glDepthMask(GL_FALSE) and a disabled depth test must not write depth: a
 * final constant-depth quad shows what the depth buffer really holds. */
#include "depth_common.h"

int main(int argc, char **argv)
{
    static const float red[3] = {1, 0, 0}, yellow[3] = {1, 1, 0}, green[3] = {0, 1, 0},
                       blue[3] = {0, 0, 1}, grey[3] = {0.6f, 0.6f, 0.6f};
    depth_begin(argc, argv);
    depth_quad(8, 8, 120, 60, 0.6f, -0.6f, red, yellow);          /* writes depth */
    glDepthMask(GL_FALSE);
    depth_quad(8, 20, 120, 48, -0.6f, 0.6f, green, blue);         /* tested, no write */
    depth_quad(8, 68, 120, 120, 0.8f, 0.8f, green, blue);         /* tested, no write */
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    depth_quad(20, 76, 60, 112, 0.9f, 0.9f, red, yellow);         /* no test: no write */
    glEnable(GL_DEPTH_TEST);
    depth_quad(0, 0, 128, 128, 0.0f, 0.0f, grey, grey);           /* probes the depth */
    return scene_end();
}
