/* Point sprites: GL_POINT_SPRITE with GL_COORD_REPLACE on unit 0, sizes 1
 * to 64, a 16x16 texture with a ring and a corner mark (so the direction of
 * t shows), GL_LINEAR, GL_MODULATE with a colour per point; top half
 * GL_POINT_SPRITE_COORD_ORIGIN GL_UPPER_LEFT (the default), bottom half
 * GL_LOWER_LEFT. Centres sit off the pixel grid by a fraction. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static const float small[9] = { 1, 2, 3, 4, 5, 6, 8, 11, 16 }, large[4] = { 23, 32, 45, 64 };
    static GLubyte img[16 * 16 * 4];
    GLuint name;
    int x, y, half, i;
    scene_begin(argc, argv, 200, 184);
    scene_ortho_pixels();
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            float dx = x - 7.5f, dy = y - 7.5f, d = (float)sqrt(dx * dx + dy * dy);
            GLubyte *p = img + 4 * (y * 16 + x);
            if (x < 4 && y < 4)
                tex_put(p, 255, 60, 40, 255);          /* mark at s, t near 0 */
            else if (d > 4.0f && d < 6.5f)
                tex_put(p, 255, 255, 255, 255);
            else
                tex_put(p, 60, 70, 120 + 8 * y, 255);
        }
    name = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    for (half = 0; half < 2; half++) {
        float base = half ? 0.0f : 92.0f, cx = 3.3f;
        glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, half ? GL_LOWER_LEFT : GL_UPPER_LEFT);
        for (i = 0; i < 9; i++) {
            glPointSize(small[i]);
            cx += small[i] / 2 + 2.0f;
            glColor3f(0.5f + 0.05f * i, 1.0f - 0.05f * i, 0.8f);
            glBegin(GL_POINTS);
            glVertex2f(cx, base + 80.37f);
            glEnd();
            cx += small[i] / 2 + 2.0f;
        }
        cx = 2.3f;
        for (i = 0; i < 4; i++) {
            glPointSize(large[i]);
            cx += large[i] / 2 + 2.0f;
            glColor3f(1.0f, 0.9f - 0.1f * i, 0.7f + 0.1f * i);
            glBegin(GL_POINTS);
            glVertex2f(cx + 0.21f, base + 36.64f);
            glEnd();
            cx += large[i] / 2 + 2.0f;
        }
    }
    glDeleteTextures(1, &name);
    return scene_end();
}
