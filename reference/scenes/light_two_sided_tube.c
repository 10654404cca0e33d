/* Two-sided lighting on an open tube seen from inside and outside, different GL_FRONT / GL_BACK materials. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_tube_scene(argc, argv, 1, GL_CCW);
}
