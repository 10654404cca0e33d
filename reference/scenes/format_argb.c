/* OSMESA_ARGB client buffer. */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_ARGB, 100, 70, 1, 0);
}
