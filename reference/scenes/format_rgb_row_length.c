/* OSMESA_RGB with OSMESA_ROW_LENGTH 64 (3-byte pixels, padded rows). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGB, 61, 45, 1, 64);
}
