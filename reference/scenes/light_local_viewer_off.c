/* Specular highlights with GL_LIGHT_MODEL_LOCAL_VIEWER off (eye vector (0,0,1)); twin of light_local_viewer_on. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_local_viewer_scene(argc, argv, 0);
}
