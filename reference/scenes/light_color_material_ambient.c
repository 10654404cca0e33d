/* glColorMaterial(GL_AMBIENT) with GL_FRONT, GL_FRONT_AND_BACK, GL_BACK (cells; glColor per vertex; GL_BACK lit with one colour, or unlit per vertex), two-sided open tube. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_color_material_scene(argc, argv, GL_AMBIENT);
}
