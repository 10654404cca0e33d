/* glDrawPixels and glCopyPixels through the pixel maps (GL_MAP_COLOR) over a
 * lit sphere: an RGBA image mapped at several zooms, with scale and bias, in
 * a display list and copied; colour-index images (bytes, shorts, floats,
 * GL_BITMAP) through the I_TO_R .. I_TO_A maps; a texture stored through the
 * maps, and a colour-index texture; glReadPixels with the maps, scale and bias, drawn back. Mesa maps red
 * and green but takes blue and alpha from a second sample of the image
 * (reference/MESA_FACTS.md "Pixel maps and pixel transfer"). */
#include <GL/glu.h>
#include <math.h>

#include "scene.h"

void glWindowPos2i(GLint x, GLint y);

#define IW 24
#define IH 16
static GLubyte rgba[IH][IW][4];
static GLubyte ci[IH][IW];
static GLshort cis[IH][IW];
static GLfloat cif[IH][IW];
static GLubyte bits[IH][4];
static GLubyte back[IH][IW][4];

static void make_images(void)
{
    for (int j = 0; j < IH; ++j)
        for (int i = 0; i < IW; ++i) {
            rgba[j][i][0] = (GLubyte)(i * 255 / (IW - 1));
            rgba[j][i][1] = (GLubyte)(j * 255 / (IH - 1));
            rgba[j][i][2] = (GLubyte)((i * 29 + j * 53) & 255);
            rgba[j][i][3] = (GLubyte)(120 + ((i * j) % 136));
            ci[j][i] = (GLubyte)((i / 3 + j / 2) * 5);
            cis[j][i] = (GLshort)(i - j * 3);
            cif[j][i] = (GLfloat)(i * 0.7 + j * 0.45);
        }
    for (int j = 0; j < IH; ++j)
        for (int k = 0; k < 4; ++k) bits[j][k] = (GLubyte)(0x5A ^ (j * 37 + k * 91));
}

static void maps(void)
{
    GLfloat r[256], g[5], b[8], a[3];
    for (int i = 0; i < 256; ++i) r[i] = 1.0f - i / 255.0f;
    for (int i = 0; i < 5; ++i) g[i] = 0.15f + i * 0.2f;
    for (int i = 0; i < 8; ++i) b[i] = (i & 1) ? 0.9f : 0.2f;
    for (int i = 0; i < 3; ++i) a[i] = 0.5f + i * 0.25f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, r);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 5, g);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 8, b);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 3, a);
    GLfloat ir[16], ig[16], ib[16], ia[16];
    for (int i = 0; i < 16; ++i) {
        ir[i] = (i % 4) / 3.0f;
        ig[i] = (i / 4) / 3.0f;
        ib[i] = 0.5f + 0.5f * sinf((float)i);
        ia[i] = 1.0f;
    }
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 16, ir);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 16, ig);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 16, ib);
    GLushort ua[16];
    for (int i = 0; i < 16; ++i) ua[i] = (GLushort)(65535 - i * 2000);
    glPixelMapusv(GL_PIXEL_MAP_I_TO_A, 16, ua);
}

static void at(int x, int y, float zx, float zy)
{
    glWindowPos2i(x, y);
    glPixelZoom(zx, zy);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 200, 160);
    make_images();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.8, 0.8, 2, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 1.5, 24, 16);
    gluDeleteQuadric(q);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);

    maps();
    /* Plain, then through the maps at several zooms. */
    at(2, 2, 1, 1);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    at(30, 2, 1, 1);
    at(58, 2, 2, 1.5f);
    at(110, 2, -1, 1);
    at(140, 30, 0.6f, 1.7f);
    /* Scale and bias before the maps. */
    glPixelTransferf(GL_RED_SCALE, 0.6f);
    glPixelTransferf(GL_GREEN_BIAS, 0.3f);
    glPixelTransferf(GL_BLUE_SCALE, 1.4f);
    glPixelTransferf(GL_ALPHA_BIAS, -0.2f);
    at(2, 30, 1, 1);
    /* Blended. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    at(60, 40, 1.5f, 1.5f);
    glDisable(GL_BLEND);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_GREEN_BIAS, 0);
    glPixelTransferf(GL_BLUE_SCALE, 1);
    glPixelTransferf(GL_ALPHA_BIAS, 0);

    /* A display list: the maps of when it runs. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glEndList();
    glWindowPos2i(110, 60);
    glPixelZoom(1, 1);
    glCallList(list);

    /* Copies through the maps (a mapped copy of the plain image). */
    glWindowPos2i(2, 56);
    glCopyPixels(2, 2, IW, IH, GL_COLOR);
    glWindowPos2i(30, 56);
    glPixelZoom(1.5f, 1);
    glCopyPixels(2, 2, IW, IH, GL_COLOR);
    glPixelZoom(1, 1);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);

    /* Colour indices: shift and offset set (Mesa does not apply them here). */
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glWindowPos2i(2, 84); glDrawPixels(IW, IH, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glWindowPos2i(30, 84); glDrawPixels(IW, IH, GL_COLOR_INDEX, GL_SHORT, cis);
    glWindowPos2i(58, 84); glDrawPixels(IW, IH, GL_COLOR_INDEX, GL_FLOAT, cif);
    glWindowPos2i(86, 84); glPixelZoom(2, 2);
    glDrawPixels(IW, IH, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
    glPixelZoom(1, 1);
    /* 29 bits a row: Mesa reads GL_BITMAP indices as one run of bits, rows not
     * padded to bytes. (A colour-index image cut at the window's edge Mesa
     * reads from memory past its rows: not drawn here.) */
    glWindowPos2i(140, 84); glDrawPixels(29, IH, GL_COLOR_INDEX, GL_BITMAP, bits);

    /* A texture stored through the maps, on a quad. */
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, IW, IH, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 200, 0, 160, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(2, 120);
    glTexCoord2f(1, 0); glVertex2f(50, 120);
    glTexCoord2f(1, 1); glVertex2f(50, 152);
    glTexCoord2f(0, 1); glVertex2f(2, 152);
    glEnd();
    /* A colour-index texture: shifted and offset when stored. */
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 2);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, IW, IH, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, ci);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(100, 120);
    glTexCoord2f(1, 0); glVertex2f(148, 120);
    glTexCoord2f(1, 1); glVertex2f(148, 152);
    glTexCoord2f(0, 1); glVertex2f(100, 152);
    glEnd();
    glDisable(GL_TEXTURE_2D);

    /* glReadPixels through the maps, scale and bias, drawn back plain. */
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glPixelTransferf(GL_GREEN_SCALE, 0.7f);
    glReadPixels(30, 2, IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, back);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    glPixelTransferf(GL_GREEN_SCALE, 1);
    glWindowPos2i(60, 125);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, back);

    scene_readpixels_check();
    return scene_end();
}
