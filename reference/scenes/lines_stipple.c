/* Line stipple: several factors and patterns; GL_LINES (the pattern restarts
 * at each line) against strips and loops (it carries on across vertices);
 * each glBegin restarts it; wide and stippled; diagonal lines. */
#include "scene.h"

static const GLushort kPatterns[] = {0x00ff, 0x0f0f, 0xaaaa, 0x1c47, 0x8001, 0xfffe, 0x3333, 0x0001};
static const GLint kFactors[] = {1, 2, 3, 1, 5, 1, 2, 7};

int main(int argc, char **argv)
{
    int k, i;
    scene_begin(argc, argv, 256, 256);
    scene_ortho_pixels();
    glEnable(GL_LINE_STIPPLE);
    for (k = 0; k < 8; k++) {
        float y = 8.0f + 30.0f * (float)k;
        glLineStipple(kFactors[k], kPatterns[k]);
        glLineWidth(k == 5 ? 3.0f : (k == 7 ? 2.0f : 1.0f));
        glShadeModel(GL_SMOOTH);
        glBegin(GL_LINES);
        for (i = 0; i < 3; i++) {
            glColor3f(1, 0.2f * (float)i, 0); glVertex2f(4.0f + 26.0f * (float)i, y + 0.5f);
            glColor3f(0, 1, 0.2f * (float)i); glVertex2f(27.5f + 26.0f * (float)i, y + 3.0f);
        }
        glEnd();
        glBegin(GL_LINE_STRIP);
        for (i = 0; i < 5; i++) {
            glColor3f(0.2f * (float)i, 0.5f, 1); glVertex2f(90.0f + 15.0f * (float)i, y + ((i & 1) ? 12.0f : 0.5f));
        }
        glEnd();
        glShadeModel(GL_FLAT);
        glBegin(GL_LINE_LOOP);
        glColor3f(1, 1, 0); glVertex2f(175.5f, y);
        glColor3f(0, 1, 1); glVertex2f(210.0f, y + 4.0f);
        glColor3f(1, 0, 1); glVertex2f(250.0f, y + 22.0f);
        glColor3f(1, 1, 1); glVertex2f(180.0f, y + 18.0f);
        glEnd();
    }
    /* the same strip in two glBegin/glEnd: the second restarts the pattern */
    glLineWidth(1.0f);
    glLineStipple(2, 0x0f0f);
    glBegin(GL_LINE_STRIP);
    glColor3f(1, 1, 1); glVertex2f(2.0f, 250.5f); glVertex2f(60.0f, 250.5f);
    glEnd();
    glBegin(GL_LINE_STRIP);
    glVertex2f(60.0f, 250.5f); glVertex2f(130.0f, 250.5f);
    glEnd();
    /* pattern 0xffff: stipple enabled but every pixel kept */
    glLineStipple(1, 0xffff);
    glBegin(GL_LINES);
    glVertex2f(140.0f, 252.5f); glVertex2f(250.0f, 247.5f);
    glEnd();
    return scene_end();
}
