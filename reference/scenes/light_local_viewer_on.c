/* Specular highlights with GL_LIGHT_MODEL_LOCAL_VIEWER on (eye vector towards the eye); twin of light_local_viewer_off. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_local_viewer_scene(argc, argv, 1);
}
