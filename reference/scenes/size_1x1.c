/* A 1x1 buffer (colour and depth), also read back with glReadPixels. */
#include "size_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 1, 1);
    size_draw();
    scene_readpixels_check();
    return scene_end();
}
