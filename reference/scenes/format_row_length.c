/* OSMESA_ROW_LENGTH 96 for a 77 pixel wide RGBA buffer (padding untouched). */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_RGBA, 77, 50, 1, 96);
}
