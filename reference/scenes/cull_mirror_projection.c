/* Winding is decided in window space: a mirrored glOrtho (left > right) and a
 * flipped glFrustum reverse which faces get culled. */
#include "cull_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 256, 128);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glViewport(0, 0, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(128, 0, 0, 128, -1, 1);          /* mirrored in x */
    glMatrixMode(GL_MODELVIEW);
    cull_draw();

    glViewport(128, 0, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, 1, -1, 1, 3);           /* upside down perspective */
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(-1.6f, -1.6f, -1.6f);
    glScalef(3.2f / 128, 3.2f / 128, 1);
    cull_draw();
    return scene_end();
}
