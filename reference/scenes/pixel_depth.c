/* glDrawPixels(GL_DEPTH_COMPONENT) then lit geometry depth-tested against
 * it: a float depth ramp, an unsigned-short bump and an unsigned-byte step
 * image written with GL_ALWAYS (their fragments also write the raster
 * colour), one zoomed, one with depth scale and bias, then a lit sphere and a
 * quad drawn with GL_LESS. */
#include <GL/glu.h>

#include "scene.h"

void glWindowPos3f(GLfloat x, GLfloat y, GLfloat z);

#define W 48
#define H 40
static GLfloat ramp[H][W];
static GLushort bump[H][W];
static GLubyte step[H / 2][W / 2];

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 128);
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            ramp[j][i] = 0.3f + 0.5f * (float)i / (W - 1) + 0.1f * (float)j / (H - 1);
            float dx = (i - W / 2) / (float)W, dy = (j - H / 2) / (float)H;
            bump[j][i] = (GLushort)(65535.0f * (0.45f + 1.2f * (dx * dx + dy * dy)));
        }
    for (int j = 0; j < H / 2; ++j)
        for (int i = 0; i < W / 2; ++i) step[j][i] = (GLubyte)(((i / 4 + j / 4) & 1) ? 110 : 160);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(0.2f, 0.2f, 0.3f);
    glWindowPos3f(4, 4, 0.5f);
    glDrawPixels(W, H, GL_DEPTH_COMPONENT, GL_FLOAT, ramp);
    glColor3f(0.3f, 0.2f, 0.2f);
    glWindowPos3f(60, 8, 0.5f);
    glPixelZoom(1.5f, 1.25f);
    glDrawPixels(W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, bump);
    glPixelZoom(1, 1);
    glColor3f(0.2f, 0.3f, 0.2f);
    glPixelTransferf(GL_DEPTH_SCALE, 0.8f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.1f);
    glWindowPos3f(20, 70, 0.5f);
    glDrawPixels(W / 2, H / 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, step);
    glPixelZoom(2, 2);
    glWindowPos3f(100, 70, 0.5f);
    glDrawPixels(W / 2, H / 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, step);
    glPixelZoom(1, 1);
    glPixelTransferf(GL_DEPTH_SCALE, 1);
    glPixelTransferf(GL_DEPTH_BIAS, 0);
    glDepthFunc(GL_LESS);

    /* Lit geometry through the depth test against the images. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 160, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_NORMALIZE);
    glColor3f(0.9f, 0.6f, 0.3f);
    glPushMatrix();
    glTranslatef(80, 60, 0);
    glScalef(50, 50, 0.9f);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 1.0, 28, 18);
    gluDeleteQuadric(q);
    glPopMatrix();
    glColor3f(0.3f, 0.8f, 0.5f);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glVertex3f(0, 30, 0.1f);
    glVertex3f(160, 30, -0.3f);
    glVertex3f(160, 40, -0.3f);
    glVertex3f(0, 40, 0.1f);
    glEnd();

    scene_readpixels_check();
    return scene_end();
}
