/* Display lists as a font: one list per glyph (small quads from a 5x7 bit
 * pattern, then a glTranslate by the advance), called with glCallLists and a
 * list base, with GL_UNSIGNED_BYTE strings and with every other name type.
 * Rows run past the right edge, so clipped glyph quads share draws with
 * unclipped ones; one glyph sets its colours inside glBegin/glEnd. */
#include <string.h>

#include "scene.h"

static unsigned pattern(int c)
{
    unsigned h = (unsigned)c * 2654435761u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h & 0x7ffffffffu;
}

static void glyph(int c)
{
    const unsigned bits = pattern(c);
    int r, k;
    for (r = 0; r < 7; r++)
        for (k = 0; k < 5; k++)
            if (bits & (1u << ((r * 5 + k) % 32))) {
                const float x = k * 2.0f, y = r * 2.0f;
                glBegin(GL_QUADS);
                if (c == 'Q') glColor3f(0.2f + 0.1f * k, 0.9f, 0.1f * r);
                glVertex2f(x, y);
                glVertex2f(x + 1.75f, y);
                if (c == 'Q') glColor3f(0.9f, 0.1f * k, 0.5f);
                glVertex2f(x + 1.75f, y + 1.75f);
                glVertex2f(x, y + 1.75f);
                glEnd();
            }
    glTranslatef(11.5f, 0, 0);
}

int main(int argc, char **argv)
{
    const char *hello = "HELLO, DISPLAY LISTS Q";
    GLuint base;
    int c;
    scene_begin(argc, argv, 200, 150);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    base = glGenLists(128);
    for (c = 32; c < 128; c++) {
        glNewList(base + c, GL_COMPILE);
        glyph(c);
        glEndList();
    }
    glListBase(base);

    glColor3f(1, 0.8f, 0.3f);
    glPushMatrix();
    glTranslatef(2.5f, 130, 0);
    glCallLists((GLsizei)strlen(hello), GL_UNSIGNED_BYTE, hello);
    glPopMatrix();

    {   /* the same glyphs by every other name type */
        const GLubyte twoBytes[6] = {0, 'A', 0, 'B', 0, 'Q'};
        const GLubyte threeBytes[6] = {0, 0, 'C', 0, 0, 'D'};
        const GLubyte fourBytes[8] = {0, 0, 0, 'E', 0, 0, 0, 'F'};
        const GLushort us[4] = {'G', 'H', 'Q', 'I'};
        const GLshort s[3] = {'J', 'K', 'L'};
        const GLint i[3] = {'M', 'N', 'O'};
        const GLuint ui[3] = {'P', 'R', 'S'};
        const GLfloat f[3] = {'T', 'U', 'V'};
        const GLbyte b[3] = {-2, -1, 0};  /* with base + 'Z': X, Y, Z */
        glColor3f(0.3f, 0.7f, 1);
        glPushMatrix();
        glTranslatef(1.25f, 108, 0);
        glCallLists(3, GL_2_BYTES, twoBytes);
        glCallLists(2, GL_3_BYTES, threeBytes);
        glCallLists(2, GL_4_BYTES, fourBytes);
        glCallLists(4, GL_UNSIGNED_SHORT, us);
        glCallLists(3, GL_SHORT, s);
        glPopMatrix();
        glColor3f(1, 0.4f, 0.6f);
        glPushMatrix();
        glTranslatef(3, 86, 0);
        glCallLists(3, GL_INT, i);
        glCallLists(3, GL_UNSIGNED_INT, ui);
        glCallLists(3, GL_FLOAT, f);
        glListBase(base + 'Z');
        glCallLists(3, GL_BYTE, b);
        glListBase(base);
        glPopMatrix();
    }

    /* A paragraph, scaled and rotated. */
    glColor3f(0.9f, 0.9f, 0.9f);
    for (c = 0; c < 4; c++) {
        static const char *lines[4] = {"THE QUICK BROWN FOX", "JUMPS OVER THE LAZY DOG", "0123456789 !?#$%&*+-", "glCallLists()"};
        glPushMatrix();
        glTranslatef(4.3f, 66 - 16.5f * c, 0);
        glRotatef(2.0f * c, 0, 0, 1);
        glScalef(0.75f, 0.75f, 1);
        glCallLists((GLsizei)strlen(lines[c]), GL_UNSIGNED_BYTE, lines[c]);
        glPopMatrix();
    }
    return scene_end();
}
