/* Fog in GL_LINEAR over a lit, smooth-shaded landscape in perspective (GL 2.1 §3.10). */
#include "fog_landscape.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 144);
    fog_landscape(GL_LINEAR, 0.0f, 2.0f, 30.0f);
    scene_readpixels_check();
    return scene_end();
}
