/* Lit smooth-shaded spheres, blending, the alpha test, smooth lines and points, glBitmap, masks and a scissored clear in an OSMesa OSMESA_RGBA / GL_FLOAT buffer. */
#include "osmesa_buffer_common.h"

int main(int argc, char **argv) { return osmesa_buffer_scene(argc, argv, OSMESA_RGBA, GL_FLOAT, 0); }
