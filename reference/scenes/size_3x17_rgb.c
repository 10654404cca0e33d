/* A 3x17 RGB buffer with y_up 0: odd rows of 9 bytes. */
#include "size_common.h"

int main(int argc, char **argv)
{
    scene_options o = {3, 17, OSMESA_RGB, 24, 0, 0};
    scene_begin_ext(argc, argv, &o);
    size_draw();
    scene_readpixels_check();
    return scene_end();
}
