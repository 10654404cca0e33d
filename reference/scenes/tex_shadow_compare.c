/* Depth textures and GL_TEXTURE_COMPARE_MODE (GL_COMPARE_R_TO_TEXTURE): a
 * 16x16 depth texture (a slope with a bump, from GL_FLOAT) on quads whose r
 * runs from 0.05 (bottom) to 0.95 (top), GL_MODULATE with a colour.
 *   top row, GL_NEAREST: every compare function (LEQUAL, GEQUAL, LESS,
 *     GREATER, EQUAL, NOTEQUAL, ALWAYS, NEVER);
 *   bottom row, GL_LINEAR: LEQUAL as GL_LUMINANCE, GL_INTENSITY and GL_ALPHA
 *     (GL_DEPTH_TEXTURE_MODE), GREATER; no comparison (the depth itself)
 *     GL_NEAREST and GL_LINEAR; LEQUAL on a GL_DEPTH_COMPONENT24 copy from
 *     GL_UNSIGNED_INT data; and (last cell) glCopyTexImage2D of a rendered
 *     sphere's depth buffer, drawn as luminance. */
#include "tex_common.h"

static void cell(int i, float r0, float r1)
{
    float x0 = (float)(i % 8 * 36 + 2), y0 = (float)((1 - i / 8) * 36 + 2);
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, r0); glVertex2f(x0, y0);
    glTexCoord3f(1.0f, 0.0f, r0); glVertex2f(x0 + 32, y0);
    glTexCoord3f(1.0f, 1.0f, r1); glVertex2f(x0 + 32, y0 + 32);
    glTexCoord3f(0.0f, 1.0f, r1); glVertex2f(x0, y0 + 32);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLenum funcs[8] = { GL_LEQUAL, GL_GEQUAL, GL_LESS, GL_GREATER, GL_EQUAL, GL_NOTEQUAL, GL_ALWAYS, GL_NEVER };
    static float depth[16 * 16];
    static GLuint depth_ui[16 * 16];
    GLuint t[3];
    int i, x, y;
    scene_begin(argc, argv, 288, 72);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            float dx = x - 9.5f, dy = y - 6.5f, d = 0.2f + 0.03f * x + 0.015f * y;
            if (dx * dx + dy * dy < 16.0f) d -= 0.25f;
            depth[y * 16 + x] = d;
            depth_ui[y * 16 + x] = (GLuint)(d * 4294967295.0);
        }

    /* the rendered depth first: a sphere in the last cell, copied, then cleared */
    glViewport(254, 2, 32, 32);
    light_ortho(1.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    light_sphere(0.9f, 24, 12);
    glGenTextures(3, t);
    glBindTexture(GL_TEXTURE_2D, t[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 254, 2, 32, 32, 0);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, 288, 72);
    scene_clear();
    scene_ortho_pixels();

    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth_ui);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.9f, 0.8f, 0.5f, 0.9f);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (i = 0; i < 8; i++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, funcs[i]);
        cell(i, 0.05f, 0.95f);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    cell(8, 0.05f, 0.95f);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    cell(9, 0.05f, 0.95f);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    cell(10, 0.05f, 0.95f);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
    cell(11, 0.05f, 0.95f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    cell(12, 0.05f, 0.95f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    cell(13, 0.05f, 0.95f);
    glBindTexture(GL_TEXTURE_2D, t[1]);
    cell(14, 0.05f, 0.95f);
    glBindTexture(GL_TEXTURE_2D, t[2]);
    cell(15, 0.0f, 0.0f);
    glDeleteTextures(3, t);
    return scene_end();
}
