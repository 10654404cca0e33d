/* Two texture units modulated: unit 0 a brick base texture (GL_MODULATE
 * with the lit colour), unit 1 a GL_LUMINANCE light map of soft spots
 * (GL_MODULATE with the result of unit 0), glMultiTexCoord2f per vertex for
 * both, on a lit wall and floor in perspective. */
#include "tex_common.h"

static void surface(int floor)
{
    int i, j, k;
    glNormal3f(0.0f, floor ? 1.0f : 0.0f, floor ? 0.0f : 1.0f);
    for (j = 0; j < 8; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 12; i++)
            for (k = 1; k >= 0; k--) {
                float u = i / 12.0f, v = (j + k) / 8.0f;
                glMultiTexCoord2f(GL_TEXTURE0, 3.0f * u, 2.0f * v);
                glMultiTexCoord2f(GL_TEXTURE1, u, v);
                if (floor)
                    glVertex3f(-2.0f + 4.0f * u, -1.0f, -(3.0f * v) + 0.0f);
                else
                    glVertex3f(-2.0f + 4.0f * u, -1.0f + 2.0f * v, -3.0f);
            }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    static GLubyte brick[32 * 32 * 4], lmap[16 * 16];
    GLuint names[2];
    int x, y;
    scene_begin(argc, argv, 160, 120);
    light_frustum(0.45f, 160.0f / 120.0f, 1.0f, 20.0f);
    tex_lights();
    /* bricks: 16x8-texel bricks, every other row shifted, grey mortar */
    for (y = 0; y < 32; y++)
        for (x = 0; x < 32; x++) {
            int row = y / 8, bx = (x + (row & 1) * 8) % 16;
            int mortar = (y % 8) == 0 || bx == 0;
            int shade = ((x * 7 + y * 13) % 5) * 6;
            if (mortar)
                tex_put(brick + 4 * (y * 32 + x), 190, 185, 175, 255);
            else
                tex_put(brick + 4 * (y * 32 + x), 170 + shade, 70 + shade, 50, 255);
        }
    /* light map: three soft spots of light on a dim base */
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            static const float spots[3][3] = { { 4.0f, 11.0f, 4.0f }, { 11.5f, 9.0f, 3.0f }, { 7.5f, 3.5f, 5.0f } };
            float v = 0.25f;
            int s;
            for (s = 0; s < 3; s++) {
                float dx = x + 0.5f - spots[s][0], dy = y + 0.5f - spots[s][1];
                float d = (float)sqrt(dx * dx + dy * dy) / spots[s][2];
                if (d < 1.0f) v += 0.75f * (1.0f - d * d);
            }
            lmap[y * 16 + x] = (GLubyte)(v > 1.0f ? 255 : 255.0f * v);
        }
    glActiveTexture(GL_TEXTURE0);
    names[0] = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, brick);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE1);
    names[1] = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lmap);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glRotatef(12.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
    glTranslatef(0.4f, 0.0f, -0.3f);
    surface(0);
    surface(1);
    glDeleteTextures(2, names);
    return scene_end();
}
