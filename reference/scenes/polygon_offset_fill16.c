/* Polygon offset on filled polygons, 16-bit depth: the units scale with the
 * depth buffer's precision (2 / 65535 a unit). */
#include "polygon_offset_common.h"

int main(int argc, char **argv)
{
    offset_scene(argc, argv, 16);
    return scene_end();
}
