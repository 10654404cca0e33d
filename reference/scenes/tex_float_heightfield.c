/* ARB_texture_float: a scientific viewer's height field. Left, a lit wavy
 * surface coloured through a 32x32 GL_LUMINANCE32F_ARB texture of heights
 * in [-0.6, 2.2] (values outside [0, 1] are kept: GL_MODULATE brightens the
 * lit colour where the height passes 1, darkens it to black below 0),
 * GL_LINEAR. Right, a lit floor receding to the horizon under a 64x64
 * GL_RGBA16F_ARB colour map with every mipmap level uploaded as floats
 * (components in [-0.5, 1.8]), GL_LINEAR_MIPMAP_LINEAR, GL_MODULATE; in
 * front of it a GL_RGB32F_ARB quad in GL_REPLACE, GL_NEAREST. */
#include "tex_common.h"
#include <math.h>

#ifndef GL_RGBA16F_ARB
#define GL_RGBA32F_ARB 0x8814
#define GL_RGB32F_ARB 0x8815
#define GL_LUMINANCE32F_ARB 0x8818
#define GL_RGBA16F_ARB 0x881A
#endif

static float heights[32 * 32];
static float levels[64 * 64 * 4];
static float quad_img[8 * 8 * 3];

static void height_texture(void)
{
    int x, y;
    for (y = 0; y < 32; y++)
        for (x = 0; x < 32; x++) {
            float u = x / 31.0f, v = y / 31.0f;
            heights[y * 32 + x] = -0.6f + 2.8f * (0.5f + 0.5f * sinf(6.0f * u + 2.0f * v) * cosf(5.0f * v - u));
        }
    tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE32F_ARB, 32, 32, 0, GL_LUMINANCE, GL_FLOAT, heights);
}

/* Each level its own float colour map: bands of hue over a ramp that runs
 * past both ends of [0, 1]. */
static void floor_texture(void)
{
    int level, size, x, y;
    tex_new(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    for (level = 0, size = 64; size >= 1; level++, size /= 2) {
        for (y = 0; y < size; y++)
            for (x = 0; x < size; x++) {
                float u = (x + 0.5f) / size, v = (y + 0.5f) / size, *p = levels + 4 * (y * size + x);
                float ramp = -0.5f + 2.3f * u;
                p[0] = ramp * (((x / 4 + y / 4) & 1) ? 1.0f : 0.6f) + 0.1f * level;
                p[1] = 1.3f - 1.6f * v;
                p[2] = 0.5f + 0.9f * sinf(9.0f * u * v + level);
                p[3] = 1.0f;
            }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA16F_ARB, size, size, 0, GL_RGBA, GL_FLOAT, levels);
    }
}

static void height_mesh(int n)
{
    int i, j, k;
    for (j = 0; j < n; j++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i <= n; i++)
            for (k = 1; k >= 0; k--) {
                float x = -1.0f + 2.0f * i / n, y = -1.0f + 2.0f * (j + k) / n, nv[3];
                float z = tex_wave(x, y, nv);
                glTexCoord2f(0.5f + 0.5f * x, 0.5f + 0.5f * y);
                glNormal3fv(nv);
                glVertex3f(x, y, z);
            }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    int x, y;
    scene_begin(argc, argv, 240, 120);

    glViewport(0, 0, 120, 120);
    light_frustum(0.42f, 1.0f, 1.0f, 20.0f);
    tex_lights();
    height_texture();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glPushMatrix();
    glTranslatef(0.05f, 0.1f, -3.9f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
    height_mesh(28);
    glPopMatrix();
    glDisable(GL_TEXTURE_2D);

    floor_texture();
    glPushMatrix();
    tex_floor_view(120, 0, 120, 120);
    glPopMatrix();

    for (y = 0; y < 8; y++)
        for (x = 0; x < 8; x++) {
            float *p = quad_img + 3 * (y * 8 + x);
            p[0] = -0.4f + 0.25f * x;
            p[1] = 1.6f - 0.3f * y;
            p[2] = ((x ^ y) & 1) ? 1.25f : -0.2f;
        }
    tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F_ARB, 8, 8, 0, GL_RGB, GL_FLOAT, quad_img);
    glViewport(0, 0, 240, 120);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0.55f, -0.95f);
    glTexCoord2f(1, 0); glVertex2f(0.95f, -0.95f);
    glTexCoord2f(1, 1); glVertex2f(0.95f, -0.35f);
    glTexCoord2f(0, 1); glVertex2f(0.55f, -0.35f);
    glEnd();
    return scene_end();
}
