/* Fog in GL_EXP over a lit, smooth-shaded landscape in perspective (GL 2.1 §3.10). */
#include "fog_landscape.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 144);
    fog_landscape(GL_EXP, 0.09f, 0, 1);
    scene_readpixels_check();
    return scene_end();
}
