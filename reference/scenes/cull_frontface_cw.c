/* glFrontFace(GL_CW) with GL_BACK culling (CCW geometry disappears), then
 * glFrontFace(GL_CCW) again with GL_FRONT culling on a mirrored copy. */
#include "cull_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 128);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_CULL_FACE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 128, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glViewport(0, 0, 128, 128);
    glFrontFace(GL_CW);
    glCullFace(GL_BACK);
    cull_draw();

    /* right half: mirrored in x, which swaps every winding */
    glViewport(128, 0, 128, 128);
    glFrontFace(GL_CCW);
    glCullFace(GL_FRONT);
    glTranslatef(128, 0, 0);
    glScalef(-1, 1, 1);
    cull_draw();
    return scene_end();
}
