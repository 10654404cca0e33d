/* GL_LIGHT_MODEL_COLOR_CONTROL = GL_SINGLE_COLOR: specular summed into the vertex colour and clamped there. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 128);
    light_color_control_draw(GL_SINGLE_COLOR, 0, 0);
    return scene_end();
}
