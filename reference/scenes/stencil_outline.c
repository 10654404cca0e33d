/* Stencil outlines: lit objects mark the stencil where they are drawn; a
 * thicker wireframe copy is drawn only outside the marks, as an outline. */
#include <GL/glu.h>
#include "scene.h"

int main(int argc, char **argv)
{
    scene_options o = {128, 128, OSMESA_RGBA, 24, 1, 0};
    GLfloat light[4] = {1, 1, 2, 0}, green[4] = {0.3f, 0.8f, 0.3f, 1};
    GLUquadric *q;
    int pass, k;
    scene_set_stencil_bits(8);
    scene_begin_ext(argc, argv, &o);
    q = gluNewQuadric();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
    for (pass = 0; pass < 2; pass++) {
        if (pass == 0) {  /* the objects, each marking its own value */
            glEnable(GL_LIGHTING);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        } else {          /* the outlines, where no object is */
            glDisable(GL_LIGHTING);
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glLineWidth(5);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glDisable(GL_DEPTH_TEST);
        }
        for (k = 0; k < 3; k++) {
            glPushMatrix();
            glTranslatef(-1.1f + 1.1f * k, (k - 1) * 0.4f, 0);
            glRotatef(30.0f * k + 20, 1, 0.5f, 0);
            if (pass == 0) {
                glStencilFunc(GL_ALWAYS, k + 1, 0xff);
            } else {
                glStencilFunc(GL_NOTEQUAL, k + 1, 0xff);
                glColor3f(k == 0, k == 1, k == 2 ? 1.0f : 0.2f);
            }
            if (k == 1)
                gluCylinder(q, 0.4, 0.2, 0.8, 16, 2);
            else
                gluSphere(q, 0.45, 16, 10);
            glPopMatrix();
        }
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gluDeleteQuadric(q);
    scene_readpixels_check();
    return scene_end();
}
