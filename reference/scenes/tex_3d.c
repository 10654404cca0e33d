/* A 3D texture (16x16x8 RGBA: r, g, b ramps along s, t, r, a light ball in
 * the middle), GL_LINEAR, GL_CLAMP_TO_EDGE, sampled through slices: three
 * quads at fixed r = 0.06, 0.45, 0.8 (r between the 8 layers) and one
 * oblique slice whose r runs from 0 to 1 across it (left, GL_REPLACE); a
 * lit cube whose faces carry their positions, scaled into [0.25, 0.75], as
 * (s, t, r) (right, GL_MODULATE). */
#include "tex_common.h"

static void slice(float x0, float y0, float size, float r0, float r1)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, r0); glVertex2f(x0, y0);
    glTexCoord3f(1.0f, 0.0f, r1); glVertex2f(x0 + size, y0);
    glTexCoord3f(1.0f, 1.0f, r1); glVertex2f(x0 + size, y0 + size);
    glTexCoord3f(0.0f, 1.0f, r0); glVertex2f(x0, y0 + size);
    glEnd();
}

int main(int argc, char **argv)
{
    static GLubyte vol[8][16][16][4];
    int x, y, z, f, v;
    GLuint name;
    scene_begin(argc, argv, 256, 128);
    for (z = 0; z < 8; z++)
        for (y = 0; y < 16; y++)
            for (x = 0; x < 16; x++) {
                float dx = (x - 7.5f) / 7.5f, dy = (y - 7.5f) / 7.5f, dz = (z - 3.5f) / 3.5f;
                float d2 = dx * dx + dy * dy + dz * dz;
                if (d2 < 0.5f)
                    tex_put(vol[z][y][x], 250, 245, 230 - 20 * z, 255);
                else
                    tex_put(vol[z][y][x], 30 + 14 * x, 30 + 14 * y, 40 + 30 * z, 100 + 20 * z);
            }
    name = tex_new(GL_TEXTURE_3D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 16, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glEnable(GL_TEXTURE_3D);

    glViewport(0, 0, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    slice(3.3f, 67.2f, 57.0f, 0.06f, 0.06f);
    slice(67.3f, 67.2f, 57.0f, 0.45f, 0.45f);
    slice(3.3f, 3.2f, 57.0f, 0.8f, 0.8f);
    slice(67.3f, 3.2f, 57.0f, 0.0f, 1.0f);

    glViewport(128, 0, 128, 128);
    light_frustum(0.3f, 1.0f, 1.0f, 20.0f);
    tex_lights();
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTranslatef(0.0f, 0.0f, -6.5f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-35.0f, 0.0f, 1.0f, 0.0f);
    {
        static const float faces[6][5][3] = {
            { { 1, 0, 0 }, { 1, -1, 1 }, { 1, -1, -1 }, { 1, 1, -1 }, { 1, 1, 1 } },
            { { -1, 0, 0 }, { -1, -1, -1 }, { -1, -1, 1 }, { -1, 1, 1 }, { -1, 1, -1 } },
            { { 0, 1, 0 }, { -1, 1, 1 }, { 1, 1, 1 }, { 1, 1, -1 }, { -1, 1, -1 } },
            { { 0, -1, 0 }, { -1, -1, -1 }, { 1, -1, -1 }, { 1, -1, 1 }, { -1, -1, 1 } },
            { { 0, 0, 1 }, { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } },
            { { 0, 0, -1 }, { 1, -1, -1 }, { -1, -1, -1 }, { -1, 1, -1 }, { 1, 1, -1 } },
        };
        glBegin(GL_QUADS);
        for (f = 0; f < 6; f++) {
            glNormal3fv(faces[f][0]);
            for (v = 1; v < 5; v++) {
                /* (s, t, r) in [0.25, 0.75]: the ball shows through the faces' middles */
                glTexCoord3f(0.5f + 0.25f * faces[f][v][0], 0.5f + 0.25f * faces[f][v][1], 0.5f + 0.25f * faces[f][v][2]);
                glVertex3fv(faces[f][v]);
            }
        }
        glEnd();
    }
    glDeleteTextures(1, &name);
    return scene_end();
}
