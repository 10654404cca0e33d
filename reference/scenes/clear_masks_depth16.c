/* clear_masks with a 16-bit depth buffer: the scissored (quad) depth clears converted as 16-bit fragment depths. */
#include "clear_masks_common.h"

int main(int argc, char **argv)
{
    return clear_masks_scene(argc, argv, 16);
}
