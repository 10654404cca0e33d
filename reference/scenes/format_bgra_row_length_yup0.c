/* OSMESA_BGRA, OSMESA_ROW_LENGTH 81 and OSMESA_Y_UP 0 together. */
#include "format_common.h"

int main(int argc, char **argv)
{
    return format_scene(argc, argv, OSMESA_BGRA, 70, 40, 0, 81);
}
