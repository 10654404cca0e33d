/* Antialiasing as programs do it: GL_LINE_SMOOTH lines and GL_POINT_SMOOTH
 * points blended with SRC_ALPHA / ONE_MINUS_SRC_ALPHA over a smooth-shaded
 * background, then with additive ONE / ONE, and a GL_MODULATE textured
 * translucent quad (blending after texturing). */
#include "scene.h"

int main(int argc, char **argv)
{
    static unsigned char tex[8 * 8 * 4];
    GLuint name;
    int i;
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glBegin(GL_QUADS);
    glColor4f(0.1f, 0.2f, 0.4f, 1.0f); glVertex2f(0, 0);
    glColor4f(0.4f, 0.1f, 0.2f, 1.0f); glVertex2f(128, 0);
    glColor4f(0.2f, 0.4f, 0.1f, 1.0f); glVertex2f(128, 128);
    glColor4f(0.3f, 0.3f, 0.3f, 1.0f); glVertex2f(0, 128);
    glEnd();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    for (i = 0; i < 8; ++i) {
        glLineWidth(1.0f + 0.5f * i);
        glColor4f(1.0f, 0.9f - 0.1f * i, 0.2f + 0.1f * i, 0.9f);
        glBegin(GL_LINES);
        glVertex2f(6.3f + 7 * i, 8.1f); glVertex2f(40.7f + 9 * i, 60.2f - 3 * i);
        glEnd();
    }
    glDisable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glBlendFunc(GL_ONE, GL_ONE);
    for (i = 0; i < 6; ++i) {
        glPointSize(3.0f + 2 * i);
        glColor4f(0.3f, 0.2f + 0.1f * i, 0.5f, 0.8f);
        glBegin(GL_POINTS);
        glVertex2f(12.4f + 19 * i, 80.3f);
        glVertex2f(14.6f + 19 * i, 84.7f);
        glEnd();
    }
    glDisable(GL_POINT_SMOOTH);
    for (i = 0; i < 64; ++i) {
        tex[4 * i + 0] = (unsigned char)(i * 4);
        tex[4 * i + 1] = (unsigned char)(255 - i * 3);
        tex[4 * i + 2] = (unsigned char)((i & 1) ? 200 : 40);
        tex[4 * i + 3] = (unsigned char)(64 + (i % 8) * 24);
    }
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_QUADS);
    glColor4f(1, 1, 1, 0.8f);
    glTexCoord2f(0, 0); glVertex2f(70, 92);
    glTexCoord2f(1, 0); glVertex2f(124, 96);
    glTexCoord2f(1, 1); glVertex2f(120, 124);
    glTexCoord2f(0, 1); glVertex2f(66, 120);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    scene_readpixels_check();
    return scene_end();
}
