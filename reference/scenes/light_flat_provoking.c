/* Flat-shaded lit meshes (triangles, strips, fans, quads, quad strips, polygons): the provoking vertex's normal decides the colour. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_flat_scene(argc, argv, 0);
}
