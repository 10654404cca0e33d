/* Colours whose value * 255 is exactly (or nearly) k + 0.5: constant-colour
 * smooth triangles, flat triangles, a smooth ramp and (top) constant-colour
 * quads seen in perspective, to pin down how colours are rounded to 8 bits. */
#include "scene.h"

int main(int argc, char **argv)
{
    static const float ties[8] = {0.3f, 0.9f, 0.5f, 0.1f, 0.7f, 1.5f / 255, 128.5f / 255, 254.5f / 255};
    int i;
    scene_begin(argc, argv, 128, 96);
    scene_ortho_pixels();
    for (i = 0; i < 8; i++) {
        float x = i * 16.0f, t = ties[i];
        glShadeModel(GL_SMOOTH);                  /* same colour at all vertices */
        glBegin(GL_TRIANGLES);
        glColor4f(t, t, 1 - t, t); glVertex2f(x + 1, 1);
        glColor4f(t, t, 1 - t, t); glVertex2f(x + 15, 3);
        glColor4f(t, t, 1 - t, t); glVertex2f(x + 4, 30);
        glEnd();
        glShadeModel(GL_FLAT);
        glBegin(GL_QUADS);
        glColor4f(t, 1 - t, t, 1 - t);
        glVertex2f(x + 1, 34); glVertex2f(x + 15, 34); glVertex2f(x + 15, 46); glVertex2f(x + 1, 46);
        glEnd();
    }
    glShadeModel(GL_SMOOTH);                      /* a smooth ramp across the buffer */
    glBegin(GL_QUADS);
    glColor3f(0, 1, 0.5f); glVertex2f(0.5f, 50); glColor3f(1, 0, 0.5f); glVertex2f(127.5f, 50);
    glColor3f(1, 0, 0.5f); glVertex2f(127.5f, 62); glColor3f(0, 1, 0.5f); glVertex2f(0.5f, 62);
    glEnd();
    /* perspective: interpolating a constant colour is not exact any more */
    glViewport(0, 64, 128, 32);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.25, 0.25, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (i = 0; i < 4; i++) {   /* left edge near (z = -1.5), right edge far (z = -6) */
        float a = -1.0f + i * 0.5f + 0.03f, b = a + 0.44f, m = 0.5f * (a + b), t = ties[i];
        glColor3f(t, 1 - t, t);
        glBegin(GL_QUAD_STRIP);
        glVertex3f(a * 1.5f, -0.3f, -1.5f); glVertex3f(a * 1.5f, 0.3f, -1.5f);
        glVertex3f(m * 3.0f, -0.6f, -3.0f); glVertex3f(m * 3.0f, 0.6f, -3.0f);
        glVertex3f(b * 6.0f, -1.2f, -6.0f); glVertex3f(b * 6.0f, 1.2f, -6.0f);
        glEnd();
    }
    scene_readpixels_check();
    return scene_end();
}
