/* A scalar (height) colour map through a 1D texture on a lit wavy surface, GL_NEAREST (see tex_common.h). */
#include "tex_common.h"

int main(int argc, char **argv)
{
    return tex_colormap_scene(argc, argv, GL_NEAREST);
}
