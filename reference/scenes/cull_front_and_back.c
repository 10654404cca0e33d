/* glCullFace(GL_FRONT_AND_BACK) with the default glFrontFace(GL_CCW). */
#include "cull_common.h"

int main(int argc, char **argv)
{
    cull_begin(argc, argv);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    cull_draw();
    /* nothing above survives; draw a marker with culling off */
    glDisable(GL_CULL_FACE);
    glColor3f(0.8f, 0.8f, 0.2f);
    glBegin(GL_TRIANGLES); glVertex2f(60, 60); glVertex2f(68, 60); glVertex2f(64, 68); glEnd();
    return scene_end();
}
