/* Blending and XOR on an OSMESA_RGB buffer (no alpha). */
#include "blend_formats.h"
int main(int argc, char **argv) { return blend_formats_draw(argc, argv, OSMESA_RGB, 0); }
