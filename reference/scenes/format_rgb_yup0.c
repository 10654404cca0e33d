/* OSMESA_RGB with OSMESA_Y_UP 0 and an odd row size (297 bytes). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGB, 99, 65, 0, 0);
}
