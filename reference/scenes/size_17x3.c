/* A 17x3 buffer (colour and depth), also read back with glReadPixels. */
#include "size_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 17, 3);
    size_draw();
    scene_readpixels_check();
    return scene_end();
}
