/* One-sided lighting (two-side off) on the open tube: the inside uses the front material and the unflipped normal. */
#include "light_common.h"

int main(int argc, char **argv)
{
    return light_tube_scene(argc, argv, 0, GL_CCW);
}
