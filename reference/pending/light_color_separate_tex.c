/* Colour control with a GL_MODULATE texture (right column): top row GL_SINGLE_COLOR, bottom row GL_SEPARATE_SPECULAR_COLOR (highlight added after texturing). */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 256);
    light_color_control_draw(GL_SINGLE_COLOR, 1, 128);
    light_color_control_draw(GL_SEPARATE_SPECULAR_COLOR, 1, 0);
    return scene_end();
}
