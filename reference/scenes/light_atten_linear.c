/* Point light with linear attenuation only (k_c = 0, k_l = 1): 1/d falloff, brighter than 1 near the light. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_atten_scene(argc, argv, 0.0f, 1.0f, 0.0f);
}
