/* GL_TRIANGLES with GL_SMOOTH shading and a distinct colour per vertex. */
#include "prim_common.h"

int main(int argc, char **argv)
{
    prim_begin(argc, argv, GL_SMOOTH);
    draw_triangles();
    return scene_end();
}
