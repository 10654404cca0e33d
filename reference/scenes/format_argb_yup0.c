/* OSMESA_ARGB with OSMESA_Y_UP 0. */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_ARGB, 90, 60, 0, 0);
}
