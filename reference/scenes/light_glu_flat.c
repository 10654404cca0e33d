/* Lit GLU quadrics with GLU_FLAT normals (one per facet, smooth shade model): gluSphere, gluCylinder, gluDisk, gluPartialDisk (depth tested, gluPerspective). */
#include "light_glu_common.h"

int main(int argc, char **argv)
{
    return light_glu_quadrics_scene(argc, argv, GLU_FLAT);
}
