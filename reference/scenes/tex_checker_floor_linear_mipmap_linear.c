/* A lit checkerboard floor receding to the horizon, GL_MODULATE, min filter GL_LINEAR_MIPMAP_LINEAR (see tex_common.h). */
#include "tex_common.h"

int main(int argc, char **argv)
{
    return tex_checker_floor_scene(argc, argv, GL_LINEAR_MIPMAP_LINEAR);
}
