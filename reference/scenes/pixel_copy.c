/* glCopyPixels(GL_COLOR) of a lit rendering: beside it, overlapping itself
 * (the source is read whole first), zoomed by positive, negative and
 * fractional factors, blended, through the depth test with the raster depth,
 * with scale and bias, a colour mask, the scissor, a source partly outside the
 * window, and from a display list. */
#include <GL/glu.h>

#include "scene.h"

void glWindowPos2i(GLint x, GLint y);
void glWindowPos3f(GLfloat x, GLfloat y, GLfloat z);

static void copy_to(int dx, int dy, float zx, float zy, int sx, int sy, int w, int h)
{
    glWindowPos2i(dx, dy);
    glPixelZoom(zx, zy);
    glCopyPixels(sx, sy, w, h, GL_COLOR);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 200, 160);

    glViewport(0, 80, 80, 80);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 2, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glColor3f(0.9f, 0.5f, 0.2f);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 1.6, 20, 14);
    glColor3f(0.2f, 0.6f, 0.9f);
    glTranslatef(0.8f, -0.8f, 1.0f);
    gluSphere(q, 0.7, 16, 10);
    gluDeleteQuadric(q);
    glDisable(GL_LIGHTING);
    glViewport(0, 0, 200, 160);
    glDisable(GL_DEPTH_TEST);

    /* Plain copies (a blit in Mesa) and overlapping ones. */
    copy_to(85, 85, 1, 1, 0, 80, 70, 70);
    copy_to(100, 100, 1, 1, 85, 85, 60, 60);      /* overlapping */
    copy_to(2, 2, 0.5f, 0.5f, 0, 80, 80, 80);
    copy_to(80, 75, -1, -1, 10, 90, 40, 30);
    copy_to(45, 2, 1.5f, 0.75f, 20, 100, 30, 30);
    copy_to(199, 2, -2, 1.25f, 10, 90, 20, 20);
    copy_to(150, 50, 0.7f, 1.3f, 0, 80, 60, 40);

    /* Blended, masked, scale and bias, scissored. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    copy_to(120, 10, 1, 1, 5, 85, 30, 30);
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
    copy_to(160, 10, 1, 1, 5, 85, 30, 30);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_BLUE_BIAS, 0.3f);
    copy_to(90, 40, 1, 1, 20, 100, 25, 25);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_BLUE_BIAS, 0);
    glEnable(GL_SCISSOR_TEST);
    glScissor(150, 100, 30, 20);
    copy_to(140, 95, 2, 2, 20, 100, 30, 20);
    glDisable(GL_SCISSOR_TEST);

    /* Depth-tested with the raster depth against the first sphere's depth. */
    glEnable(GL_DEPTH_TEST);
    glWindowPos3f(10, 82, 0.45f);
    glPixelZoom(1, 1);
    glCopyPixels(100, 100, 50, 50, GL_COLOR);
    glDisable(GL_DEPTH_TEST);

    /* A display list. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glCopyPixels(0, 80, 30, 30, GL_COLOR);
    glEndList();
    glWindowPos2i(165, 125);
    glPixelZoom(1, 1);
    glCallList(list);

    scene_readpixels_check();
    return scene_end();
}
