/* Alpha-tested foliage: crossed quads with a leafy RGBA texture (smooth alpha
 * edges under GL_LINEAR, modulated by vertex colours) in perspective, depth
 * tested against each other and a ground quad, drawn in no particular order:
 * the discarded texels must write no depth (llvmpipe's late depth test). */
#include <math.h>

#include "scene.h"

#include <GL/glu.h>

#define TS 64

static void leaf_texture(void)
{
    static GLubyte texels[TS * TS * 4];
    for (int y = 0; y < TS; ++y)
        for (int x = 0; x < TS; ++x) {
            float u = (x + 0.5f) / TS * 2 - 1, v = (y + 0.5f) / TS;
            /* Five blades from the bottom centre, each a soft-edged wedge. */
            float best = 0;
            for (int b = 0; b < 5; ++b) {
                float lean = (b - 2) * 0.35f;
                float cx = lean * v, width = 0.18f * (1.0f - v) + 0.02f;
                float d = fabsf(u - cx) / width;
                float a = 1.0f - d;
                if (a > best) best = a;
            }
            if (best < 0) best = 0;
            if (best > 1) best = 1;
            GLubyte *p = texels + 4 * (y * TS + x);
            p[0] = (GLubyte)(40 + 60 * v);
            p[1] = (GLubyte)(120 + 120 * best);
            p[2] = (GLubyte)(30 + 20 * (1 - v));
            p[3] = (GLubyte)(255 * best);
        }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TS, TS, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

static void tuft(float x, float z, float h, float angle)
{
    glPushMatrix();
    glTranslatef(x, 0, z);
    glRotatef(angle, 0, 1, 0);
    for (int i = 0; i < 2; ++i) {
        glRotatef(90, 0, 1, 0);
        glBegin(GL_QUADS);
        glColor4f(0.8f, 1.0f, 0.8f, 1.0f);
        glTexCoord2f(0, 0); glVertex3f(-h * 0.5f, 0, 0);
        glTexCoord2f(1, 0); glVertex3f(h * 0.5f, 0, 0);
        glColor4f(1.0f, 1.0f, 0.7f, 0.9f);
        glTexCoord2f(1, 1); glVertex3f(h * 0.5f, h, 0);
        glTexCoord2f(0, 1); glVertex3f(-h * 0.5f, h, 0);
        glEnd();
    }
    glPopMatrix();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 160);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, 192.0 / 160.0, 0.5, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.3, 1.6, 5.5, 0, 0.6, 0, 0, 1, 0);
    glEnable(GL_DEPTH_TEST);

    /* The ground, untextured, not alpha tested. */
    glColor3f(0.45f, 0.32f, 0.2f);
    glBegin(GL_QUADS);
    glVertex3f(-6, 0, -6); glVertex3f(-6, 0, 6); glVertex3f(6, 0, 6); glVertex3f(6, 0, -6);
    glEnd();

    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    leaf_texture();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    scene_srand(7);
    /* Front to back first (the worst case for a depth write of discarded texels). */
    for (int i = 0; i < 14; ++i) {
        float x = scene_randf(-2.5f, 2.5f), z = 2.0f - i * 0.35f;
        tuft(x, z, scene_randf(0.8f, 1.6f), scene_randf(0, 90));
    }
    /* A softer threshold for a second row. */
    glAlphaFunc(GL_GEQUAL, 0.25f);
    for (int i = 0; i < 8; ++i) {
        float x = scene_randf(-2.5f, 2.5f), z = -3.0f + i * 0.4f;
        tuft(x, z, scene_randf(1.0f, 2.0f), scene_randf(0, 90));
    }
    scene_readpixels_check();
    return scene_end();
}
