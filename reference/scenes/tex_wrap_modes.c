/* Every wrap mode on one quad each (columns: GL_REPEAT, GL_CLAMP,
 * GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT), texture
 * coordinates from -1.5 to 2.5 (t from -1.5 to 2.5 too), a border colour;
 * top row GL_LINEAR, bottom row GL_NEAREST, GL_REPLACE. A third row wraps s
 * and t differently (s GL_REPEAT / t the column's mode) under a slight
 * rotation, GL_LINEAR. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static const GLenum modes[5] = { GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT };
    static const GLfloat border[4] = { 0.95f, 0.2f, 0.75f, 0.6f };
    static GLubyte img[8 * 8 * 4];
    GLuint names[15];
    int x, y, row, col;
    scene_begin(argc, argv, 300, 180);
    scene_ortho_pixels();
    /* 8x8: a colour gradient with a dark frame one texel wide and a bright
     * texel in one corner, so every edge and the orientation show */
    for (y = 0; y < 8; y++)
        for (x = 0; x < 8; x++) {
            GLubyte *p = img + 4 * (y * 8 + x);
            int frame = x == 0 || y == 0 || x == 7 || y == 7;
            if (x == 6 && y == 6)
                tex_put(p, 255, 255, 255, 255);
            else if (frame)
                tex_put(p, 30 + 20 * x, 40, 60 + 20 * y, 200);
            else
                tex_put(p, 40 + 30 * x, 60 + 25 * y, 200 - 20 * x, 255);
        }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (row = 0; row < 3; row++)
        for (col = 0; col < 5; col++) {
            GLenum filter = row == 1 ? GL_NEAREST : GL_LINEAR;
            float x0 = col * 60 + 3.3f, y0 = (2 - row) * 60 + 3.6f, s = 53.0f;
            names[row * 5 + col] = tex_new(GL_TEXTURE_2D, filter, filter, modes[col]);
            if (row == 2)
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
            glPushMatrix();
            if (row == 2) {
                glTranslatef(x0 + s / 2, y0 + s / 2, 0.0f);
                glRotatef(9.0f, 0.0f, 0.0f, 1.0f);
                glTranslatef(-(x0 + s / 2), -(y0 + s / 2), 0.0f);
            }
            glBegin(GL_QUADS);
            glTexCoord2f(-1.5f, -1.5f); glVertex2f(x0, y0);
            glTexCoord2f(2.5f, -1.5f);  glVertex2f(x0 + s, y0);
            glTexCoord2f(2.5f, 2.5f);   glVertex2f(x0 + s, y0 + s);
            glTexCoord2f(-1.5f, 2.5f);  glVertex2f(x0, y0 + s);
            glEnd();
            glPopMatrix();
        }
    glDeleteTextures(15, names);
    return scene_end();
}
