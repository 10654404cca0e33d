/* Point light with constant attenuation only (k_c = 2.5): uniform dimming of wall, floor and sphere. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_atten_scene(argc, argv, 2.5f, 0.0f, 0.0f);
}
