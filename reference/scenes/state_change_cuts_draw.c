/* Setters that change a value and change it back, between glBegin/glEnd pairs
 * of smooth GL_QUADS: whether Mesa flushes its buffered vertices on each
 * change decides whether the quad clipped at the right edge shares a draw
 * with (and so decides the split of) the quads after it. One row per setter. */
#include "scene.h"
#include "smooth_quad.h"

static void change_and_back(int which)
{
    switch (which) {
    case 0: glMatrixMode(GL_PROJECTION); glMatrixMode(GL_MODELVIEW); break;
    case 1: glClearDepth(0.5); glClearDepth(1.0); break;
    case 2: glClearColor(0.5f, 0, 0, 0); glClearColor(0, 0, 0, 0); break;
    case 3: glHint(GL_FOG_HINT, GL_NICEST); glHint(GL_FOG_HINT, GL_DONT_CARE); break;
    case 4: glPixelStorei(GL_UNPACK_ALIGNMENT, 1); glPixelStorei(GL_UNPACK_ALIGNMENT, 4); break;
    case 5: glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE); glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); break;
    case 6: glDepthFunc(GL_LEQUAL); glDepthFunc(GL_LESS); break;
    case 7: glShadeModel(GL_FLAT); glShadeModel(GL_SMOOTH); break;
    case 8: glFrontFace(GL_CW); glFrontFace(GL_CCW); break;
    case 9: glEnable(GL_LIGHT3); glDisable(GL_LIGHT3); break;
    case 10: glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 2.0f); glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 0.0f); break;
    case 11: glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); glProvokingVertex(GL_LAST_VERTEX_CONVENTION); break;
    case 12: glDepthRange(0, 0.5); glDepthRange(0, 1); break;
    case 13: glPushMatrix(); glPopMatrix(); break;
    case 14: glFlush(); break;
    case 15: { GLfloat m[16]; glGetFloatv(GL_MODELVIEW_MATRIX, m); } break;
    }
}

int main(int argc, char **argv)
{
    int row;
    scene_begin(argc, argv, 160, 192);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0, 0, 0, 0);
    for (row = 0; row < 16; row++) {
        float y = 2 + row * 12;
        glTranslatef(0, 0, 0);  /* a real change: each row is a draw of its own */
        quad(155, y, 10);       /* crosses the right edge: clipped */
        change_and_back(row);
        quad(4, y, 10);
        quad(40, y, 10);
    }
    return scene_end();
}
