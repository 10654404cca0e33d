/* glProvokingVertex(GL_FIRST_VERTEX_CONVENTION) with GL_FLAT for all six
 * triangle-producing primitives (one 128x128 cell each). */
#include "prim_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 384, 256);
    glShadeModel(GL_FLAT);
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    prim_cell(0); draw_triangles();
    prim_cell(1); draw_triangle_strip();
    prim_cell(2); draw_triangle_fan();
    prim_cell(3); draw_quads();
    prim_cell(4); draw_quad_strip();
    prim_cell(5); draw_polygon();
    return scene_end();
}
