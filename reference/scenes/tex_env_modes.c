/* Every texture environment mode for every base format on lit spheres, GL_SINGLE_COLOR (see tex_common.h). */
#include "tex_common.h"

int main(int argc, char **argv)
{
    return tex_env_modes_scene(argc, argv, GL_SINGLE_COLOR);
}
