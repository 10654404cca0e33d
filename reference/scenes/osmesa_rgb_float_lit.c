/* The osmesa_*_lit drawing in an OSMesa OSMESA_RGB / GL_FLOAT buffer: three channels, no alpha in the buffer. */
#include "osmesa_buffer_common.h"

int main(int argc, char **argv) { return osmesa_buffer_scene(argc, argv, OSMESA_RGB, GL_FLOAT, 0); }
