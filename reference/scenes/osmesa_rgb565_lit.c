/* Lit smooth-shaded spheres, blending, the alpha test, smooth lines and points, glBitmap, masks and a scissored clear in an OSMesa OSMESA_RGB_565 / GL_UNSIGNED_SHORT_5_6_5 buffer. */
#include "osmesa_buffer_common.h"

int main(int argc, char **argv) { return osmesa_buffer_scene(argc, argv, OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 0); }
