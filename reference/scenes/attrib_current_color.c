/* glPopAttrib(GL_CURRENT_BIT) and Mesa's vbo: colours whose value * 255 is
 * k + 0.5, on quad strips seen in perspective, where a colour interpolated
 * as per-vertex data rounds differently from a constant one. glPopAttrib
 * draws what is buffered and the restored colour is a constant again, as
 * after any state change, whether the colour had become per-vertex data
 * outside glBegin/glEnd (rows 0, 1) or inside (rows 2, 3). */
#include "scene.h"

static const float ties[4] = {0.3f, 0.9f, 0.5f, 0.1f};

static void strip(int col, int row)
{
    float a = -1.0f + col * 0.5f + 0.03f, b = a + 0.44f, m = 0.5f * (a + b);
    float y = -0.75f + row * 0.5f;
    glBegin(GL_QUAD_STRIP);
    glVertex3f(a * 1.5f, (y - 0.2f) * 1.5f, -1.5f); glVertex3f(a * 1.5f, (y + 0.2f) * 1.5f, -1.5f);
    glVertex3f(m * 3.0f, (y - 0.2f) * 3.0f, -3.0f); glVertex3f(m * 3.0f, (y + 0.2f) * 3.0f, -3.0f);
    glVertex3f(b * 6.0f, (y - 0.2f) * 6.0f, -6.0f); glVertex3f(b * 6.0f, (y + 0.2f) * 6.0f, -6.0f);
    glEnd();
}

static void tie(int i) { glColor3f(ties[i], 1 - ties[i], ties[i]); }

int main(int argc, char **argv)
{
    int row;
    scene_begin(argc, argv, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    for (row = 0; row < 4; row++) {
        glTranslatef(0, 0, 0);  /* each row starts with a fresh vertex format */
        tie(0);
        strip(0, row);
        glPushAttrib(row == 1 ? GL_ALL_ATTRIB_BITS : GL_CURRENT_BIT);
        if (row < 2) {
            tie(1);          /* outside, vertices buffered: per-vertex data */
            strip(1, row);
        } else {
            glBegin(GL_QUAD_STRIP);  /* the colour set inside glBegin/glEnd */
            tie(row == 2 ? 1 : 2);
            glVertex3f(0, 0, -20); glVertex3f(0, 0, -20); glVertex3f(0, 0, -20); glVertex3f(0, 0, -20);
            glEnd();
            strip(1, row);
        }
        glPopAttrib();       /* back to ties[0], drawn as a constant */
        strip(2, row);
        tie(3);
        strip(3, row);
    }
    return scene_end();
}
