/* glDepthFunc(GL_EQUAL) against overlapping, coplanar and far-plane geometry. */
#include "depth_common.h"

int main(int argc, char **argv)
{
    depth_begin(argc, argv);
    depth_draw(GL_EQUAL);
    return scene_end();
}
