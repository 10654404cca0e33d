/* Shadow volumes: a lit floor and blocks, closed shadow volumes drawn into
 * the stencil two-sided in one pass (glStencilOpSeparate: GL_INCR_WRAP on
 * front faces, GL_DECR_WRAP on back faces, z-pass), then a darkening pass
 * where the count is not zero. */
#include "scene.h"

static void box(float x0, float y0, float z0, float x1, float y1, float z1)
{
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);  glVertex3f(x0, y0, z1); glVertex3f(x1, y0, z1); glVertex3f(x1, y1, z1); glVertex3f(x0, y1, z1);
    glNormal3f(0, 0, -1); glVertex3f(x0, y0, z0); glVertex3f(x0, y1, z0); glVertex3f(x1, y1, z0); glVertex3f(x1, y0, z0);
    glNormal3f(1, 0, 0);  glVertex3f(x1, y0, z0); glVertex3f(x1, y1, z0); glVertex3f(x1, y1, z1); glVertex3f(x1, y0, z1);
    glNormal3f(-1, 0, 0); glVertex3f(x0, y0, z0); glVertex3f(x0, y0, z1); glVertex3f(x0, y1, z1); glVertex3f(x0, y1, z0);
    glNormal3f(0, 1, 0);  glVertex3f(x0, y1, z0); glVertex3f(x0, y1, z1); glVertex3f(x1, y1, z1); glVertex3f(x1, y1, z0);
    glNormal3f(0, -1, 0); glVertex3f(x0, y0, z0); glVertex3f(x1, y0, z0); glVertex3f(x1, y0, z1); glVertex3f(x0, y0, z1);
    glEnd();
}

/* A block on its post and its shadow volume, straight down (a light above). */
static void blocks(int volumes)
{
    int i;
    for (i = 0; i < 3; i++) {
        const float x = -1.2f + 1.2f * i, z = (i - 1) * 0.5f, h = 0.6f + 0.3f * i;
        if (volumes)
            box(x - 0.3f, -0.5f, z - 0.3f, x + 0.3f, h - 0.01f, z + 0.3f);
        else
            box(x - 0.3f, h, z - 0.3f, x + 0.3f, h + 0.3f, z + 0.3f);
    }
}

int main(int argc, char **argv)
{
    scene_options o = {160, 120, OSMESA_RGBA, 24, 1, 0};
    GLfloat light[4] = {0.3f, 1, 0.5f, 0}, floorc[4] = {0.7f, 0.7f, 0.6f, 1}, blockc[4] = {0.8f, 0.4f, 0.2f, 1};
    scene_set_stencil_bits(8);
    scene_begin_ext(argc, argv, &o);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.375, 0.375, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, -0.6f, -4.5f);
    glRotatef(30, 1, 0, 0);
    glRotatef(-20, 0, 1, 0);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* the lit scene */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, floorc);
    glBegin(GL_QUADS);
    glNormal3f(0, 1, 0);
    glVertex3f(-2.5f, 0, -2); glVertex3f(-2.5f, 0, 2); glVertex3f(2.5f, 0, 2); glVertex3f(2.5f, 0, -2);
    glEnd();
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blockc);
    blocks(0);
    glDisable(GL_LIGHTING);

    /* the volumes: both faces in one pass, no colour, no depth writes */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    blocks(1);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* the shadow: where the count is not zero */
    glStencilFunc(GL_NOTEQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.15f, 0.15f, 0.25f);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
    glEnd();
    /* and, as a check of the counts, the pixels with a count of 255 (a volume
     * seen from behind only) in red */
    glStencilFunc(GL_EQUAL, 255, 0xff);
    glColor3f(1, 0, 0);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(1, 1); glVertex2f(-1, 1);
    glEnd();
    glDepthMask(GL_TRUE);
    scene_readpixels_check();
    return scene_end();
}
