/* OSMESA_RGB client buffer (3 bytes per pixel, no alpha). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGB, 100, 70, 1, 0);
}
