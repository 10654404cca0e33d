/* OSMESA_BGRA client buffer. */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_BGRA, 100, 70, 1, 0);
}
