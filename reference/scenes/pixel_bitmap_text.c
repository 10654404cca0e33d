/* GLUT-style bitmap text (glBitmap with freeglut's unpack settings) over a lit
 * sphere: depth-tested raster positions, the scissor, a text run that leaves
 * the window on the left and right, bitmaps in a display list, skip pixels and
 * rows, an invalid raster position that draws nothing. */
#include <GL/glu.h>
#include <string.h>

#include "scene.h"

/* A made-up 8x13 font: glyph c is a deterministic pattern with a box. */
static GLubyte font[96][13];

static void make_font(void)
{
    for (int c = 0; c < 96; ++c)
        for (int r = 0; r < 13; ++r) {
            unsigned v = (unsigned)(c * 37 + r * 11);
            GLubyte b = (GLubyte)((v * 2654435761u) >> 24);
            if (r == 0 || r == 12) b = 0x7e;
            b |= 0x81 & (GLubyte)(r & 1 ? 0x80 : 0x01);
            font[c][r] = (c == 0) ? 0 : b;
        }
}

/* freeglut's glutBitmapCharacter. */
static void bitmap_char(int c)
{
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(8, 13, 1.0f, 2.0f, 9.0f, 0.0f, font[(c - 32) & 95]);
    glPopClientAttrib();
}

static void text(const char *s)
{
    for (; *s; ++s) bitmap_char(*s);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 128);
    make_font();

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

    /* Text in front of and behind the sphere (raster z through the depth test). */
    glColor3f(1, 1, 0.2f);
    glRasterPos3f(-1.8f, 0.9f, 1.0f);
    text("In front");
    glColor3f(0.2f, 1, 1);
    glRasterPos3f(-1.9f, -0.2f, -1.2f);
    text("behind the sphere!");
    glColor4f(1, 0.3f, 0.6f, 0.5f);
    glRasterPos3f(-0.5f, -1.0f, 0.0f);
    text("Half");

    /* Window-space text in ortho. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 160, 0, 128);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glColor3f(1, 1, 1);
    glRasterPos2f(2.6f, 114.2f);
    text("GLUT 8x13 text");
    /* Starts inside, moves off the right edge and on past it. */
    glColor3f(0.5f, 1, 0.5f);
    glRasterPos2i(120, 100);
    text("off the edge and more");
    /* Moves the raster position off the left with an empty bitmap (valid). */
    glRasterPos2i(4, 88);
    glBitmap(0, 0, 0, 0, -30, 0, NULL);
    glColor3f(1, 0.5f, 0.2f);
    text("from the left side");
    /* The scissor. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(20, 0, 60, 20);
    glColor3f(0.8f, 0.8f, 1);
    glRasterPos2i(4, 6);
    text("scissored text!!");
    glDisable(GL_SCISSOR_TEST);

    /* Bitmaps in a display list: the bits are unpacked at compile time. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    text("list");
    glEndList();
    memset(font, 0, sizeof font);
    glColor3f(1, 0.2f, 0.2f);
    glRasterPos2i(100, 40);
    glCallList(list);
    make_font();

    /* Skip pixels and rows, row length, alignment 2. */
    {
        static GLubyte big[40 * 4];
        for (int i = 0; i < (int)sizeof big; ++i) big[i] = (GLubyte)(i * 29 + 7);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 30);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
        glColor3f(0.3f, 0.6f, 1);
        glRasterPos2f(10.5f, 30.99995f);
        glBitmap(25, 20, 0.5f, 0.0f, 0, 0, big);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }

    /* An invalid raster position: nothing is drawn. */
    glRasterPos2f(-10, -10);
    glColor3f(1, 1, 1);
    text("never");
    /* Far outside the window by a huge move. */
    glRasterPos2i(50, 60);
    glBitmap(0, 0, 0, 0, 1e9f, -1e9f, NULL);
    text("far");

    scene_readpixels_check();
    return scene_end();
}
