/* Point light with quadratic attenuation only (k_c = 0, k_q = 1): 1/d^2 falloff. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_atten_scene(argc, argv, 0.0f, 0.0f, 1.0f);
}
