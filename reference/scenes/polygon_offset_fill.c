/* Polygon offset on filled polygons, 24-bit depth: coplanar lit strips drawn
 * twice, the second pass offset by factors and units of either sign. */
#include "polygon_offset_common.h"

int main(int argc, char **argv)
{
    offset_scene(argc, argv, 24);
    return scene_end();
}
