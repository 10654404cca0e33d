/* GL_SEPARATE_SPECULAR_COLOR without texturing: primary and secondary clamped and interpolated separately, summed per fragment. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 128);
    light_color_control_draw(GL_SEPARATE_SPECULAR_COLOR, 0, 0);
    return scene_end();
}
