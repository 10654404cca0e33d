/* Blending (destination alpha too) and XOR on an OSMESA_ARGB buffer. */
#include "blend_formats.h"
int main(int argc, char **argv) { return blend_formats_draw(argc, argv, OSMESA_ARGB, 1); }
