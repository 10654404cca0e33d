/* glClear with a colour mask per channel, with the depth mask off, and under the scissor (a box inside the buffer, one past its edges, an empty one, one covering it all); then quads drawn against the depth the clears left (24-bit depth). */
#include "clear_masks_common.h"

int main(int argc, char **argv)
{
    return clear_masks_scene(argc, argv, 24);
}
