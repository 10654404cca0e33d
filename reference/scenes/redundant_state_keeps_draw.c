/* Setters called with the value the state already has, between glBegin/glEnd
 * pairs of smooth GL_QUADS: Mesa returns before it flushes, so the pairs stay
 * one draw and the quad clipped at the right edge decides how every quad of
 * the draw is split. One row per setter; each row starts with a clipped quad. */
#include "scene.h"
#include "smooth_quad.h"

static void redundant(int which)
{
    static const GLfloat diffuse0[4] = {1, 1, 1, 1};
    static const GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1};
    GLint vp[4];
    switch (which) {
    case 0: glDepthFunc(GL_LESS); break;
    case 1: glShadeModel(GL_SMOOTH); break;
    case 2: glDepthMask(GL_TRUE); break;
    case 3: glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse0); break;
    case 4: glEnable(GL_DEPTH_TEST); break;
    case 5: glDisable(GL_CULL_FACE); break;
    case 6: glGetIntegerv(GL_VIEWPORT, vp); glViewport(vp[0], vp[1], vp[2], vp[3]); break;
    case 7: glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); break;
    case 8: glCullFace(GL_BACK); glFrontFace(GL_CCW); break;
    case 9: glClearColor(0, 0, 0, 0); glClearDepth(1.0); break;
    case 10: glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient); glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0); break;
    case 11: glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE); break;
    case 12: glDepthRange(0, 1); break;
    case 13: glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_DONT_CARE); break;
    case 14: glMatrixMode(GL_MODELVIEW); break;
    case 15: glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f); break;
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
        redundant(row);
        quad(4, y, 10);
        redundant(row);
        quad(40, y, 10);
        quad(80, y, 10);
    }
    return scene_end();
}
