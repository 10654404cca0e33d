/* A 640x480 buffer (colour and depth), also read back with glReadPixels. */
#include "size_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 640, 480);
    size_draw();
    scene_readpixels_check();
    return scene_end();
}
