/* OSMESA_BGR client buffer (3 bytes per pixel, no alpha).  Mesa 22 refuses it in
 * OSMesaMakeCurrent; the scene then compares "refused" on both sides. */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_BGR, 100, 70, 1, 0);
}
