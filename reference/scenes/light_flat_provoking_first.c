/* light_flat_provoking with glProvokingVertex(GL_FIRST_VERTEX_CONVENTION). */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_flat_scene(argc, argv, 1);
}
