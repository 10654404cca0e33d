/*
 * feedback_pixels: the raster position (glRasterPos in its forms, under a
 * perspective and an orthographic projection, a depth range, positions
 * outside the view volume) and the feedback tokens of glBitmap, glDrawPixels
 * and glCopyPixels for each feedback type; glBitmap moving the raster
 * position; the raster position's hits in GL_SELECT; the raster state queries.
 */
#include "fb_common.h"

enum { W = 100, H = 80 };
static GLfloat buf[2048];
static GLuint sel[256];
static const GLubyte bits[32] = {0xff, 0x81, 0x81, 0xff, 0x18, 0x18, 0x3c, 0x7e};

static void print_raster(const char *title) {
    GLfloat p[4], c[4], t[4], d;
    GLboolean valid;
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, t);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    printf("raster %s: valid %d pos %.9g %.9g %.9g %.9g colour %.9g %.9g %.9g %.9g tex %.9g %.9g %.9g %.9g dist %.9g\n",
           title, valid, p[0], p[1], p[2], p[3], c[0], c[1], c[2], c[3], t[0], t[1], t[2], t[3], d);
}

static void triangle(void) {
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.2f, -0.2f, -2.0f); glVertex3f(0.2f, -0.2f, -2.0f); glVertex3f(0.0f, 0.2f, -2.0f);
    glEnd();
}

static void positions(void) {
    /* primitives and pixel tokens interleaved: the order is kept */
    triangle();
    glRasterPos3f(0.1f, 0.1f, -2.0f);
    triangle();
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    triangle();
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
    triangle();
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
    triangle();
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glRasterPos3f(0.3f, -0.2f, -2.5f);
    glBitmap(8, 8, 1.0f, 2.0f, 1.5f, -2.25f, bits);
    glBitmap(8, 8, 0.0f, 0.0f, 1.5f, -2.25f, bits);
    glBitmap(0, 0, 0.0f, 0.0f, -4.0f, 3.0f, NULL);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, bits);
    glCopyPixels(0, 0, 2, 2, GL_COLOR);
    glPassThrough(1.0f);
    glColor4f(1.5f, -0.5f, 0.25f, 2.0f); /* beyond [0,1] */
    glTexCoord4f(0.5f, 0.25f, -2.0f, 2.0f);
    glRasterPos2i(0, 0);
    glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, bits);
    glRasterPos4f(0.2f, 0.3f, -1.5f, 0.75f);
    glCopyPixels(1, 1, 1, 1, GL_DEPTH);
    glRasterPos2d(-0.25, 0.125);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    static const GLint iv[3] = {0, 0, -3};
    glRasterPos3iv(iv);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    static const GLshort sv[4] = {1, 1, -4, 2};
    glRasterPos4sv(sv);
    glBitmap(8, 8, 0, 0, 0, 0, bits);
    glPassThrough(2.0f);
    glRasterPos3f(30.0f, 0.0f, -2.5f); /* outside: invalid, nothing fed back */
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
    glRasterPos3f(0.0f, 0.0f, -9.0f); /* beyond the far plane */
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    glRasterPos3f(0.1f, 0.1f, -1.0f); /* on the near plane */
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    glPassThrough(3.0f);
}

static void run(GLenum type, const char *title) {
    for (int i = 0; i < 2048; ++i) buf[i] = -777.0f;
    glFeedbackBuffer(2048, type, buf);
    glRenderMode(GL_FEEDBACK);
    positions();
    fb_error(title);
    GLint n = glRenderMode(GL_RENDER);
    fb_print_feedback(title, type, n, buf, 2048);
    print_raster(title);
}

int main(void) {
    fb_begin(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 6.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(7.0f, 0.2f, 1.0f, 0.1f);
    print_raster("initial");

    run(GL_2D, "2D");
    run(GL_3D, "3D");
    run(GL_3D_COLOR, "3D_COLOR");
    run(GL_3D_COLOR_TEXTURE, "3D_COLOR_TEXTURE");
    run(GL_4D_COLOR_TEXTURE, "4D_COLOR_TEXTURE");
    glDepthRange(0.2, 0.7);
    glViewport(10, 5, 70, 60);
    run(GL_4D_COLOR_TEXTURE, "4D_COLOR_TEXTURE, depth range and viewport");
    glViewport(0, 0, W, H);
    glDepthRange(0.0, 1.0);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.9f, 0.1f, 0.3f);
    glRasterPos2i(10, 20);
    print_raster("ortho");
    glBitmap(0, 0, 0, 0, 5.5f, -3.25f, NULL); /* moves the raster position in GL_RENDER */
    print_raster("ortho, moved");
    run(GL_3D_COLOR, "ortho 3D_COLOR");

    /* GL_SELECT: a valid raster position is a hit; bitmaps and pixels are not */
    glSelectBuffer(256, sel);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    glRasterPos3f(50.0f, 40.0f, 0.5f);
    glLoadName(2);
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
    glCopyPixels(0, 0, 1, 1, GL_COLOR);
    glLoadName(3);
    glRasterPos3f(500.0f, 40.0f, 0.5f); /* invalid: no hit */
    glLoadName(4);
    glRasterPos3f(20.0f, 10.0f, -0.25f);
    glRasterPos3f(30.0f, 10.0f, 0.75f);
    fb_print_select("raster positions", glRenderMode(GL_RENDER), sel, 256);
    return fb_end();
}
