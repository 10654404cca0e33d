/* A font texture drawn as text quads (no blending: that is issue 15). The
 * glyphs are 5x7 bitmaps drawn into 8x8 cells of a 128x64 texture with a
 * soft one-texel fringe, uploaded as GL_LUMINANCE_ALPHA and as GL_ALPHA.
 * Rows, top down:
 *   1: GL_LUMINANCE_ALPHA, GL_MODULATE, GL_NEAREST, 2 pixels a texel, a
 *      colour per line;
 *   2: the same, GL_LINEAR, 3 pixels a texel, on a slanted baseline;
 *   3: GL_LUMINANCE_ALPHA, GL_LINEAR, minified (0.8 pixel a texel);
 *   4: GL_ALPHA, GL_REPLACE (colour from glColor, alpha from the glyph);
 *   5: GL_LUMINANCE_ALPHA, GL_MODULATE on a lit panel in perspective. */
#include "tex_common.h"

/* 5x7 glyphs, one byte per row (bit 4 = left column), top row first. */
static const struct { char c; unsigned char rows[7]; } font[] = {
    { '0', { 0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e } }, { '1', { 0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e } },
    { '2', { 0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f } }, { '3', { 0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e } },
    { '4', { 0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02 } }, { '5', { 0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e } },
    { '6', { 0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e } }, { '7', { 0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08 } },
    { '8', { 0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e } }, { '9', { 0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c } },
    { 'A', { 0x0e, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11 } }, { 'B', { 0x1e, 0x11, 0x11, 0x1e, 0x11, 0x11, 0x1e } },
    { 'C', { 0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e } }, { 'D', { 0x1c, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1c } },
    { 'E', { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f } }, { 'F', { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10 } },
    { 'G', { 0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f } }, { 'H', { 0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11 } },
    { 'I', { 0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e } }, { 'L', { 0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f } },
    { 'M', { 0x11, 0x1b, 0x15, 0x15, 0x11, 0x11, 0x11 } }, { 'N', { 0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11 } },
    { 'O', { 0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e } }, { 'P', { 0x1e, 0x11, 0x11, 0x1e, 0x10, 0x10, 0x10 } },
    { 'R', { 0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11 } }, { 'S', { 0x0f, 0x10, 0x10, 0x0e, 0x01, 0x01, 0x1e } },
    { 'T', { 0x1f, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04 } }, { 'U', { 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e } },
    { 'W', { 0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0a } }, { 'X', { 0x11, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0x11 } },
    { 'Y', { 0x11, 0x11, 0x0a, 0x04, 0x04, 0x04, 0x04 } }, { '.', { 0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c } },
    { ',', { 0x00, 0x00, 0x00, 0x00, 0x0c, 0x04, 0x08 } }, { '!', { 0x04, 0x04, 0x04, 0x04, 0x04, 0x00, 0x04 } },
};

/* Texel (x, y) of glyph cell (cx, cy): 255 on the glyph, 90 next to it. */
static int glyph_texel(const unsigned char rows[7], int x, int y)
{
    int dx, dy, near = 0;
    /* the cell's texel rows run bottom up; glyph rows 0..6 sit in cell rows 7..1 */
    int gy = 7 - y, gx = x - 1;
    if (gy >= 0 && gy < 7 && gx >= 0 && gx < 5 && (rows[gy] >> (4 - gx) & 1))
        return 255;
    for (dy = -1; dy <= 1; dy++)
        for (dx = -1; dx <= 1; dx++) {
            int ny = gy + dy, nx = gx + dx;
            if (ny >= 0 && ny < 7 && nx >= 0 && nx < 5 && (rows[ny] >> (4 - nx) & 1))
                near = 1;
        }
    return near ? 90 : 0;
}

/* Draws `s` from (x, y), each glyph w x h units, advancing by w (and by
 * `rise` in y per glyph); texture cell of character c: (c % 16, c / 16). */
static void text(const char *s, float x, float y, float w, float h, float rise)
{
    glBegin(GL_QUADS);
    for (; *s; s++, x += w, y += rise) {
        int c = (unsigned char)*s & 127;
        float s0 = (c % 16) / 16.0f, t0 = (c / 16) / 8.0f, s1 = s0 + 1.0f / 16.0f, t1 = t0 + 1.0f / 8.0f;
        glTexCoord2f(s0, t0); glVertex2f(x, y);
        glTexCoord2f(s1, t0); glVertex2f(x + w, y + rise);
        glTexCoord2f(s1, t1); glVertex2f(x + w, y + rise + h);
        glTexCoord2f(s0, t1); glVertex2f(x, y + h);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    static GLubyte la[64][128][2], alpha[64][128];
    GLuint names[3];
    unsigned g;
    int x, y;
    scene_begin(argc, argv, 256, 200);
    for (g = 0; g < sizeof font / sizeof font[0]; g++) {
        int cx = (font[g].c & 127) % 16, cy = (font[g].c & 127) / 16;
        for (y = 0; y < 8; y++)
            for (x = 0; x < 8; x++) {
                int v = glyph_texel(font[g].rows, x, y);
                la[cy * 8 + y][cx * 8 + x][0] = (GLubyte)v;
                la[cy * 8 + y][cx * 8 + x][1] = (GLubyte)v;
                alpha[cy * 8 + y][cx * 8 + x] = (GLubyte)v;
            }
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    names[0] = tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 128, 64, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    names[1] = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 128, 64, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    names[2] = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 128, 64, 0, GL_ALPHA, GL_UNSIGNED_BYTE, alpha);
    glEnable(GL_TEXTURE_2D);
    scene_ortho_pixels();

    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    glColor3f(1.0f, 0.9f, 0.4f);
    text("HELLO, TEXT!", 2.0f, 182.0f, 16.0f, 16.0f, 0.0f);
    glColor3f(0.5f, 0.9f, 1.0f);
    text("0123456789", 2.0f, 164.0f, 16.0f, 16.0f, 0.0f);
    glBindTexture(GL_TEXTURE_2D, names[1]);
    glColor3f(0.9f, 0.5f, 0.9f);
    text("GL FIXED", 3.3f, 126.4f, 24.0f, 24.0f, 1.7f);
    glColor3f(1.0f, 1.0f, 1.0f);
    text("ABCDEFGHILMNOPRSTUWXY 0123456789.", 1.5f, 110.3f, 6.4f, 6.4f, 0.0f);
    glBindTexture(GL_TEXTURE_2D, names[2]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glColor3f(0.3f, 0.8f, 0.4f);
    text("ALPHA ONLY", 2.7f, 84.2f, 20.0f, 20.0f, 0.0f);

    /* a lit panel in perspective carrying text */
    glBindTexture(GL_TEXTURE_2D, names[1]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glViewport(0, 0, 256, 80);
    light_frustum(0.3f, 256.0f / 80.0f, 1.0f, 20.0f);
    tex_lights();
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.8f, 0.5f, 1.0f);
    glTranslatef(0.2f, 0.0f, -4.5f);
    glRotatef(-25.0f, 0.0f, 1.0f, 0.0f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    text("LIT PANEL 42", -2.4f, -0.5f, 0.4f, 0.4f, 0.0f);
    text("SO FAR, SO GOOD", -2.4f, 0.0f, 0.32f, 0.32f, 0.0f);
    glDeleteTextures(3, names);
    return scene_end();
}
