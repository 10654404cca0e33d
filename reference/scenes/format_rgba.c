/* OSMESA_RGBA client buffer, OSMESA_Y_UP 1 (bottom row first). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGBA, 100, 70, 1, 0);
}
