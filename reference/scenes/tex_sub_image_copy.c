/* Texture updates between drawn frames. Frame 1: a lit sphere and some
 * flat triangles. From it: glCopyTexImage2D (GL_RGB8, 64x64; GL_LUMINANCE,
 * 32x32), glCopyTexSubImage2D into a checker texture that also gets a
 * glTexSubImage2D patch (with unpack row length and skips), glCopyTexImage1D
 * and glCopyTexSubImage1D / glTexSubImage1D into 1D textures. Frame 2
 * (cleared): those textures on quads (GL_NEAREST, GL_REPLACE; the 64x64 copy
 * at one texel a pixel). Then glCopyTexSubImage2D of frame 2 into the first
 * texture and a glTexSubImage2D bar into the checker, and the bottom row
 * (no clear) shows them again, one on a lit sphere (GL_LINEAR, GL_MODULATE). */
#include "tex_common.h"

static void quad2(float x0, float y0, float w, float h)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f); glVertex2f(x0, y0);
    glTexCoord2f(1.0f, 0.0f); glVertex2f(x0 + w, y0);
    glTexCoord2f(1.0f, 1.0f); glVertex2f(x0 + w, y0 + h);
    glTexCoord2f(0.0f, 1.0f); glVertex2f(x0, y0 + h);
    glEnd();
}

static void pixels(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 256.0, 0.0, 128.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glViewport(0, 0, 256, 128);
}

int main(int argc, char **argv)
{
    static GLubyte checker[32 * 32 * 4], patch[12 * 8 * 4], ramp[32 * 4], bar[32 * 3 * 4], bits[4 * 4];
    static const GLubyte c0[4] = { 250, 250, 240, 255 }, c1[4] = { 40, 90, 160, 255 };
    GLuint t[5];
    int i;
    scene_begin(argc, argv, 256, 128);

    /* ---- frame 1 ---- */
    glViewport(0, 0, 128, 128);
    light_ortho(1.0f, 1.0f);
    tex_lights();
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.5f, 0.3f, 1.0f);
    light_sphere(0.8f, 32, 16);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    pixels();
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.9f, 0.3f); glVertex2f(10.3f, 8.2f); glVertex2f(60.1f, 20.7f); glVertex2f(22.4f, 70.9f);
    glColor3f(0.9f, 0.9f, 0.2f); glVertex2f(70.3f, 100.2f); glVertex2f(120.6f, 90.7f); glVertex2f(100.4f, 126.1f);
    glEnd();

    glGenTextures(5, t);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 16, 16, 64, 64, 0);

    tex_checker(checker, 32, 32, 4, c0, c1);
    for (i = 0; i < 12 * 8; i++)
        tex_put(patch + 4 * i, 200 + i % 12 * 4, 30 + i / 12 * 20, 40, 255);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 12);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 5, 8, 6, GL_RGBA, GL_UNSIGNED_BYTE, patch);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 18, 14, 40, 50, 12, 16);

    glBindTexture(GL_TEXTURE_2D, t[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 30, 10, 32, 32, 0);

    for (i = 0; i < 32; i++)
        tex_ramp(i / 31.0f, ramp + 4 * i);
    for (i = 0; i < 4; i++)
        tex_put(bits + 4 * i, 255, 255 * (i & 1), 255, 255);
    glBindTexture(GL_TEXTURE_1D, t[3]);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 8, 30, 64, 16);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 26, 4, GL_RGBA, GL_UNSIGNED_BYTE, bits);
    glBindTexture(GL_TEXTURE_1D, t[4]);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 10, 70, 32, 0);

    /* ---- frame 2 ---- */
    scene_clear();
    pixels();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    quad2(2.0f, 62.0f, 64.0f, 64.0f);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    quad2(68.0f, 62.0f, 64.0f, 64.0f);
    glBindTexture(GL_TEXTURE_2D, t[2]);
    quad2(134.0f, 62.0f, 64.0f, 64.0f);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_1D);
    glBindTexture(GL_TEXTURE_1D, t[3]);
    quad2(200.0f, 62.0f, 54.0f, 64.0f);
    glBindTexture(GL_TEXTURE_1D, t[4]);
    quad2(200.0f, 2.0f, 54.0f, 56.0f);
    glDisable(GL_TEXTURE_1D);

    /* ---- updates from frame 2, drawn below it ---- */
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 16, 16, 76, 70, 32, 32);
    for (i = 0; i < 32 * 3; i++)
        tex_put(bar + 4 * i, 230, 40 + 2 * (i % 32), 60, 255);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 20, 32, 3, GL_RGBA, GL_UNSIGNED_BYTE, bar);
    glEnable(GL_TEXTURE_2D);
    quad2(68.0f, 2.0f, 56.0f, 56.0f);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    quad2(134.0f, 2.0f, 56.0f, 56.0f);

    glViewport(2, 2, 60, 56);
    light_ortho(1.0f, 60.0f / 56.0f);
    tex_lights();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    tex_sphere(0.95f, 32, 16, 1.0f);
    glDeleteTextures(5, t);
    return scene_end();
}
