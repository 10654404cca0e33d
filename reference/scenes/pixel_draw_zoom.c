/* glDrawPixels of a generated RGBA image over a lit sphere: at several raster
 * positions, zoomed by positive, negative and fractional factors, depth-tested
 * with the raster depth, blended, with skip pixels and rows, other formats and
 * types (RGB, LUMINANCE, BGRA, 5_6_5, 4_4_4_4, UNSIGNED_SHORT, FLOAT), pixel
 * scale and bias, off the window's edges, and from a display list. */
#include <GL/glu.h>

#include "scene.h"

/* GL 1.4, not declared by every gl.h. */
void glWindowPos2f(GLfloat x, GLfloat y);
void glWindowPos2i(GLint x, GLint y);

#define IW 13
#define IH 11
static GLubyte rgba[IH][IW][4];
static GLubyte rgb[IH][IW][3];
static GLubyte lum[IH][IW];
static GLushort us[IH][IW][4];
static GLushort p565[IH][IW];
static GLushort p4444[IH][IW];
static GLfloat fl[IH][IW][4];

static void make_images(void)
{
    for (int j = 0; j < IH; ++j)
        for (int i = 0; i < IW; ++i) {
            GLubyte r = (GLubyte)(i * 255 / (IW - 1)), g = (GLubyte)(j * 255 / (IH - 1));
            GLubyte b = (GLubyte)(((i ^ j) & 1) ? 230 : 40);
            GLubyte a = (GLubyte)(90 + ((i + j) * 13) % 160);
            if (i == 0 || j == 0 || i == IW - 1 || j == IH - 1) { r = 250; g = 250; b = 250; }
            rgba[j][i][0] = r; rgba[j][i][1] = g; rgba[j][i][2] = b; rgba[j][i][3] = a;
            rgb[j][i][0] = b; rgb[j][i][1] = r; rgb[j][i][2] = g;
            lum[j][i] = (GLubyte)((r + g) / 2 + 8);
            us[j][i][0] = (GLushort)(r * 257 + 100); us[j][i][1] = (GLushort)(g * 250);
            us[j][i][2] = (GLushort)(b * 256); us[j][i][3] = 65535;
            p565[j][i] = (GLushort)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
            p4444[j][i] = (GLushort)(((r >> 4) << 12) | ((b >> 4) << 8) | ((g >> 4) << 4) | 0xf);
            fl[j][i][0] = r / 255.0f * 1.1f; fl[j][i][1] = g / 300.0f; fl[j][i][2] = b / 255.0f; fl[j][i][3] = 1;
        }
}

static void at(float x, float y, float zx, float zy)
{
    glWindowPos2f(x, y);
    glPixelZoom(zx, zy);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 200, 160);
    make_images();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    /* The lit scene. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.8, 0.8, 2, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 1.5, 24, 16);
    gluDeleteQuadric(q);
    glDisable(GL_LIGHTING);

    /* Through the depth test with the raster depth: in front of, behind the sphere. */
    glRasterPos3f(-0.3f, 0.1f, 1.2f);
    glPixelZoom(3, 3);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glRasterPos3f(-0.9f, -0.6f, -1.0f);
    glPixelZoom(2.5f, 1.75f);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glDisable(GL_DEPTH_TEST);

    /* Window positions: integer, fractional (rounded), negative and fractional zooms. */
    at(2, 2, 1, 1);
    at(20.4f, 2.6f, 1, 1);
    at(60, 14, -1, 1);
    at(62, 16, 1, -1);
    at(90, 20, -2, -1.5f);
    at(100, 2, 0.5f, 0.5f);
    at(110, 2, 0.7f, 1.3f);
    at(125, 2, 1.5f, 0.33f);
    at(150, 3, 2.25f, 1);
    at(2, 140, 1.1f, 1.9f);
    at(190, 150, 2, 2);     /* off the top right */
    at(-5, 60, 1, 1);       /* off the left */
    at(-9, 80, 3, 1);

    /* Blended. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    at(70, 60, 4, 4);
    at(120, 100, -3, 2);
    glDisable(GL_BLEND);

    /* Alpha test and a colour mask. */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    at(150, 40, 2, 2);
    glDisable(GL_ALPHA_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    at(175, 70, 1, 2);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* Skip pixels and rows, row length. */
    glPixelStorei(GL_UNPACK_ROW_LENGTH, IW);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    glWindowPos2i(30, 40);
    glPixelZoom(1, 1);
    glDrawPixels(IW - 4, IH - 3, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);

    /* Other formats and types. */
    glPixelZoom(1, 1);
    glWindowPos2i(2, 100); glDrawPixels(IW, IH, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    glWindowPos2i(18, 100); glDrawPixels(IW, IH, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glWindowPos2i(34, 100); glDrawPixels(IW, IH, GL_BGRA, GL_UNSIGNED_BYTE, rgba);
    glWindowPos2i(50, 100); glDrawPixels(IW, IH, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565);
    glWindowPos2i(66, 100); glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, p4444);
    glWindowPos2i(2, 118); glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_SHORT, us);
    glWindowPos2i(18, 118); glDrawPixels(IW, IH, GL_RGBA, GL_FLOAT, fl);
    glWindowPos2i(34, 118); glDrawPixels(IW, IH, GL_ALPHA, GL_UNSIGNED_BYTE, lum);

    /* Scale and bias. */
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glPixelTransferf(GL_BLUE_SCALE, 1.5f);
    glWindowPos2i(50, 118); glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_GREEN_BIAS, 0);
    glPixelTransferf(GL_BLUE_SCALE, 1);

    /* A display list: the image is copied when compiled. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glEndList();
    rgba[5][5][0] = 0; rgba[5][5][1] = 0; rgba[5][5][2] = 255;
    glWindowPos2i(70, 130);
    glPixelZoom(2, 2);
    glCallList(list);

    /* An invalid raster position draws nothing. */
    glRasterPos3f(0, 0, -20);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);

    scene_readpixels_check();
    return scene_end();
}
