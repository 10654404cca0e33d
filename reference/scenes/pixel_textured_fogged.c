/* Textured and fogged glDrawPixels, glCopyPixels and glBitmap text over a
 * fogged, lit sphere, with GL_TEXTURE_2D left on: Mesa runs the current
 * fixed-function fragment program on pixel rectangles, so they are textured
 * at the CURRENT texture coordinates (not the raster position's), under each
 * texture environment, with a second unit, a mipmapped texture and the
 * unlit colour sum on bitmaps; fog is on throughout and Mesa does not fog
 * pixel rectangles (MESA_FACTS.md "Pixel rectangles: texturing"). */
#include <GL/glu.h>
#include <string.h>

#include "scene.h"

void glWindowPos2i(GLint x, GLint y);
void glActiveTexture(GLenum unit);
void glMultiTexCoord2f(GLenum unit, GLfloat s, GLfloat t);
void glSecondaryColor3f(GLfloat r, GLfloat g, GLfloat b);

#define IW 13
#define IH 11
static GLubyte rgba[IH][IW][4];
static GLubyte font[96][13];

static void make_data(void)
{
    for (int j = 0; j < IH; ++j)
        for (int i = 0; i < IW; ++i) {
            rgba[j][i][0] = (GLubyte)(i * 255 / (IW - 1));
            rgba[j][i][1] = (GLubyte)(j * 255 / (IH - 1));
            rgba[j][i][2] = (GLubyte)(((i ^ j) & 1) ? 230 : 40);
            rgba[j][i][3] = (GLubyte)(90 + ((i + j) * 13) % 160);
        }
    for (int c = 0; c < 96; ++c)
        for (int r = 0; r < 13; ++r) {
            unsigned v = (unsigned)(c * 37 + r * 11);
            GLubyte b = (GLubyte)((v * 2654435761u) >> 24);
            if (r == 0 || r == 12) b = 0x7e;
            font[c][r] = (c == 0) ? 0 : (GLubyte)(b | 0x81);
        }
}

static void text(const char *s)
{
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (; *s; ++s) glBitmap(8, 13, 1.0f, 2.0f, 9.0f, 0.0f, font[(*s - 32) & 95]);
}

/* A 16x16 texture with mipmaps: a checker in colour, each level its own tint. */
static GLuint make_texture(int mip)
{
    GLuint id;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    static GLubyte t[16 * 16 * 4];
    for (int level = 0, n = 16; n >= 1; ++level, n /= 2) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                GLubyte *p = t + (j * n + i) * 4;
                int on = ((i / 2) ^ (j / 2)) & 1;
                p[0] = (GLubyte)(on ? 240 : 30 + level * 40);
                p[1] = (GLubyte)(i * 15);
                p[2] = (GLubyte)(on ? 60 : 200 - level * 30);
                p[3] = (GLubyte)(on ? 255 : 160);
            }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
        if (!mip) break;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mip ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mip ? GL_LINEAR : GL_NEAREST);
    return id;
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 200, 160);
    make_data();

    /* The fogged, lit scene. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.8, 0.8, 2, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 3.0f);
    glFogf(GL_FOG_END, 7.0f);
    GLfloat fogColor[4] = {0.3f, 0.35f, 0.5f, 1};
    glFogfv(GL_FOG_COLOR, fogColor);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 1.5, 24, 16);
    gluDeleteQuadric(q);
    glDisable(GL_LIGHTING);

    GLuint nearestTex = make_texture(0), mipTex = make_texture(1);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, nearestTex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    /* glDrawPixels through the depth test, textured at the current
     * coordinates: the raster position's (set before) are not the ones used. */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexCoord2f(0.9f, 0.9f);
    glRasterPos3f(-0.3f, 0.1f, 1.7f);
    glTexCoord2f(0.3f, 0.1f);
    glPixelZoom(3, 3);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glTexCoord2f(0.6f, 0.8f);
    glRasterPos3f(-0.9f, -0.6f, -1.0f);
    glPixelZoom(2.5f, 1.75f);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glDisable(GL_DEPTH_TEST);
    glPixelZoom(1, 1);

    /* Every environment, in window space. */
    static const GLenum modes[] = {GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD, GL_MODULATE};
    GLfloat envColor[4] = {0.2f, 0.9f, 0.4f, 0.5f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
    for (int m = 0; m < 5; ++m) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[m]);
        glTexCoord2f(0.05f + 0.2f * m, 0.55f);
        glWindowPos2i(2 + 16 * m, 2);
        glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    }
    /* GL_COMBINE with the primary colour (the image's texel). */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
    glTexCoord2f(0.4f, 0.4f);
    glWindowPos2i(84, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);

    /* A mipmapped texture: constant coordinates sample the base level with
     * the magnification filter; a second unit adds (its coordinates are a
     * varying glDrawPixels does not carry). */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glBindTexture(GL_TEXTURE_2D, mipTex);
    glTexCoord2f(0.47f, 0.53f);
    glWindowPos2i(100, 2);
    glPixelZoom(1.5f, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelZoom(1, 1);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, nearestTex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glMultiTexCoord2f(GL_TEXTURE1, 0.8f, 0.2f);
    glActiveTexture(GL_TEXTURE0);
    glWindowPos2i(124, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);

    /* Bitmap text on two units at the current coordinates (unit 1's now a
     * constant: glBitmap leaves the vertex program alone). */
    glColor3f(1, 1, 0.6f);
    glWindowPos2i(4, 140);
    text("two units");

    /* The colour sum without lighting adds the current secondary colour. */
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glEnable(GL_COLOR_SUM);
    glSecondaryColor3f(0.1f, 0.4f, 0.0f);
    glColor3f(0.6f, 0.3f, 0.9f);
    glTexCoord2f(0.2f, 0.7f);
    glWindowPos2i(4, 124);
    text("colour sum");
    glDisable(GL_TEXTURE_2D);
    glColor3f(0.2f, 0.2f, 0.5f);
    glSecondaryColor3f(0.7f, 0.5f, 2.0f);
    glWindowPos2i(100, 124);
    text("plain+");
    glEnable(GL_TEXTURE_2D);

    /* Under lighting the colour sum reads a varying the bitmap lacks: 0. */
    glEnable(GL_LIGHTING);
    glColor3f(1, 1, 1);
    glWindowPos2i(4, 108);
    text("lit text");
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_SUM);

    /* A texture matrix on unit 1 makes its coordinates varying: (0, 0, 0, 0). */
    glActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.25f, 0, 0);
    glMatrixMode(GL_MODELVIEW);
    glActiveTexture(GL_TEXTURE0);
    glColor3f(0.4f, 0.7f, 1);
    glTexCoord2f(0.85f, 0.15f);
    glWindowPos2i(100, 108);
    text("matrix");
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);

    /* Bitmaps cached and drawn later take the state of the last glBitmap:
     * texturing turned off before the flush still textures them. */
    glColor3f(1, 0.6f, 0.3f);
    glTexCoord2f(0.9f, 0.35f);
    glWindowPos2i(4, 92);
    text("cached");
    glDisable(GL_TEXTURE_2D);
    glFlush();
    glEnable(GL_TEXTURE_2D);

    /* glCopyPixels through the quad (blending on) is textured too. */
    glBindTexture(GL_TEXTURE_2D, nearestTex);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glTexCoord2f(0.1f, 0.9f);
    glWindowPos2i(150, 40);
    glCopyPixels(2, 2, 40, 14, GL_COLOR);
    glDisable(GL_BLEND);

    /* A display list's glDrawPixels and glBitmap, textured at replay. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    text("L");
    glEndList();
    glTexCoord2f(0.7f, 0.45f);
    glWindowPos2i(150, 70);
    glCallList(list);

    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    scene_readpixels_check();
    return scene_end();
}
