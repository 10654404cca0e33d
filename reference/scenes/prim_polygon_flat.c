/* GL_POLYGON with GL_FLAT shading and a distinct colour per vertex. */
#include "prim_common.h"

int main(int argc, char **argv)
{
    prim_begin(argc, argv, GL_FLAT);
    draw_polygon();
    return scene_end();
}
