/* Two-sided lighting with glFrontFace(GL_CW): the tube's outside becomes the back face (back material, flipped normal). */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_tube_scene(argc, argv, 1, GL_CW);
}
