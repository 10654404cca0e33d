/* Textured lines and points (not sprites): a 1D colour ramp (GL_REPEAT,
 * GL_LINEAR, GL_MODULATE) along GL_LINES of widths 1 and 3 in every
 * direction, along a lit GL_LINE_STRIP spiral and a GL_LINE_LOOP; a 2D
 * checker on wide lines with (s, t) per vertex; GL_POINTS of sizes 1 and 5,
 * each with its own texture coordinate (one texel colour per point). */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static GLubyte ramp[16 * 4], checker[8 * 8 * 4];
    static const GLubyte c0[4] = { 250, 240, 200, 255 }, c1[4] = { 60, 80, 170, 255 };
    GLuint t[2];
    int i;
    scene_begin(argc, argv, 192, 160);
    scene_ortho_pixels();
    for (i = 0; i < 16; i++)
        tex_ramp(i / 15.0f, ramp + 4 * i);
    tex_checker(checker, 8, 8, 2, c0, c1);
    t[0] = tex_new(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
    t[1] = tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_1D);
    glColor3f(1.0f, 1.0f, 1.0f);

    /* a fan of lines from (48.3, 112.4), widths 1 (even) and 3 (odd) */
    for (i = 0; i < 16; i++) {
        double a = 2.0 * LIGHT_PI * i / 16 + 0.1;
        glLineWidth(i & 1 ? 3.0f : 1.0f);
        glBegin(GL_LINES);
        glTexCoord1f(0.0f);
        glVertex2f(48.3f, 112.4f);
        glTexCoord1f(1.7f);
        glVertex2f(48.3f + 44.0f * (float)cos(a), 112.4f + 44.0f * (float)sin(a));
        glEnd();
    }
    glLineWidth(1.0f);
    /* a loop */
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 7; i++) {
        double a = 2.0 * LIGHT_PI * i / 7;
        glTexCoord1f(i / 3.0f);
        glVertex2f(144.2f + 40.0f * (float)cos(a), 112.7f + 40.0f * (float)sin(a));
    }
    glEnd();
    /* wide lines with a 2D texture */
    glDisable(GL_TEXTURE_1D);
    glEnable(GL_TEXTURE_2D);
    glLineWidth(5.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 3; i++) {
        glTexCoord2f(0.0f, 0.1f * i);
        glVertex2f(6.4f, 60.3f - 9.0f * i);
        glTexCoord2f(3.0f, 0.1f * i + 0.9f);
        glVertex2f(90.6f, 48.1f - 9.0f * i);
    }
    glEnd();
    glLineWidth(1.0f);
    glDisable(GL_TEXTURE_2D);
    /* points: one texture coordinate each */
    glEnable(GL_TEXTURE_1D);
    for (i = 0; i < 24; i++) {
        glPointSize(i & 1 ? 5.0f : 1.0f);
        glBegin(GL_POINTS);
        glTexCoord1f(i / 23.0f);
        glVertex2f(8.3f + 7.0f * (i % 12), 14.6f + 10.0f * (i / 12));
        glEnd();
    }
    glPointSize(1.0f);
    /* a lit line strip spiral in perspective */
    glViewport(96, 0, 96, 72);
    light_frustum(0.4f, 96.0f / 72.0f, 1.0f, 20.0f);
    tex_lights();
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i <= 120; i++) {
        double a = 6.0 * LIGHT_PI * i / 120;
        float r = 0.2f + 1.1f * i / 120.0f;
        glTexCoord1f(i / 30.0f);
        glNormal3f((float)cos(a), (float)sin(a), 0.4f);
        glVertex3f(r * (float)cos(a), r * (float)sin(a), -0.6f + 1.2f * i / 120.0f);
    }
    glEnd();
    glDeleteTextures(2, t);
    return scene_end();
}
