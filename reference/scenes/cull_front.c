/* glCullFace(GL_FRONT) with the default glFrontFace(GL_CCW). */
#include "cull_common.h"

int main(int argc, char **argv)
{
    cull_begin(argc, argv);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    cull_draw();
    return scene_end();
}
