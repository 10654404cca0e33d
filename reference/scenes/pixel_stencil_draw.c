/* glDrawPixels(GL_STENCIL_INDEX) as a mask, then a lit scene drawn through
 * the stencil test: a ring of unsigned-byte values, a zoomed float checker,
 * a mirrored unsigned-short stripe image under a write mask and a scissor,
 * and a depth-stencil (GL_UNSIGNED_INT_24_8) block that also sets depth;
 * then lit spheres where the stencil is 1, a quad where it is 2, and a
 * background fan where it is neither. */
#include <GL/glu.h>

#include "scene.h"

void glWindowPos2i(GLint x, GLint y);

#define W 40
#define H 36
static GLubyte ring[H][W];
static GLfloat checker[12][16];
static GLushort stripes[20][24];
static GLuint block[16][20];

static void sphere(GLUquadric *q, float x, float y, float r)
{
    glPushMatrix();
    glTranslatef(x, y, 0);
    glScalef(r, r, 0.5f);
    gluSphere(q, 1.0, 24, 16);
    glPopMatrix();
}

int main(int argc, char **argv)
{
    scene_options o = {160, 128, OSMESA_RGBA, 24, 1, 0};
    scene_set_stencil_bits(8);
    scene_begin_ext(argc, argv, &o);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            float dx = i - W / 2 + 0.5f, dy = j - H / 2 + 0.5f, d = dx * dx + dy * dy;
            ring[j][i] = d < 64 ? 2 : d < 300 ? 1 : 0;
        }
    for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 16; ++i) checker[j][i] = ((i / 4 + j / 3) & 1) ? 1.0f : 2.3f;
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 24; ++i) stripes[j][i] = (GLushort)(0x0100 + ((i / 3) & 1 ? 1 : 2) + 0x40);
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 20; ++i) block[j][i] = ((GLuint)((0.25f + 0.025f * i) * 16777215.0f) << 8) | (j < 8 ? 1 : 2);

    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glWindowPos2i(6, 8);
    glDrawPixels(W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, ring);
    glPixelZoom(2.5f, 1.75f);
    glWindowPos2i(52, 6);
    glDrawPixels(16, 12, GL_STENCIL_INDEX, GL_FLOAT, checker);
    glPixelZoom(-1.5f, 1.0f);
    glStencilMask(0x03);  /* 0x141 and 0x142 keep 1 and 2 */
    glScissor(0, 60, 150, 40);
    glEnable(GL_SCISSOR_TEST);
    glWindowPos2i(150, 50);
    glDrawPixels(24, 20, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT, stripes);
    glDisable(GL_SCISSOR_TEST);
    glStencilMask(0xff);
    glPixelZoom(1.25f, 1.25f);
    glWindowPos2i(20, 70);
    glDrawPixels(20, 16, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, block);
    glPixelZoom(1, 1);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 160, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);

    /* Lit spheres where the stencil is 1. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    GLUquadric *q = gluNewQuadric();
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glColor3f(0.9f, 0.5f, 0.2f);
    sphere(q, 26, 26, 22);
    sphere(q, 80, 18, 26);
    glColor3f(0.3f, 0.6f, 0.9f);
    sphere(q, 120, 78, 30);
    sphere(q, 40, 84, 20);
    gluDeleteQuadric(q);
    glDisable(GL_LIGHTING);

    /* A shaded quad where it is 2, through the depth test against the block. */
    glStencilFunc(GL_EQUAL, 2, 0xff);
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.9f, 0.2f);
    glVertex3f(0, 0, 0.8f);
    glColor3f(0.2f, 0.9f, 0.4f);
    glVertex3f(160, 0, 0.8f);
    glColor3f(0.8f, 0.2f, 0.7f);
    glVertex3f(160, 128, 0.0f);
    glColor3f(0.2f, 0.3f, 0.9f);
    glVertex3f(0, 128, 0.0f);
    glEnd();

    /* A background where neither. */
    glStencilFunc(GL_GREATER, 1, 0xff);  /* 1 > stencil: 0 */
    glColor3f(0.25f, 0.25f, 0.3f);
    glRectf(0, 0, 160, 128);

    scene_readpixels_check();
    return scene_end();
}
