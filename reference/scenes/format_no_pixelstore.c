/* OSMesaPixelStore never called: Mesa's default orientation (Y up). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGBA, 80, 60, -1, 0);
}
