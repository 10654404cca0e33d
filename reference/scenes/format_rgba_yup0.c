/* OSMESA_RGBA with OSMESA_Y_UP 0 (top row first). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGBA, 100, 70, 0, 0);
}
