/* Point light with constant, linear and quadratic attenuation combined. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_atten_scene(argc, argv, 0.3f, 0.4f, 0.6f);
}
