/* Mesa draws the buffered glBegin/glEnd vertices at a state change only when
 * the value really changes (and never at glMatrixMode, glClearColor or
 * glClearDepth). Each cell: a clipped quad, one such call, then a smooth quad
 * inside the view. Merged into one draw with the clipped quad, the inside
 * quad splits (0,1,3)(1,2,3); drawn alone, (0,1,2)(0,2,3). */
#define GL_GLEXT_PROTOTYPES 1
#include "scene.h"

static void clipped_quad(void)
{
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);
    glVertex2f(-10, -10);
    glVertex2f(5, -10);
    glVertex2f(5, 5);
    glVertex2f(-10, 5);
    glEnd();
}

static void inside_quad(int cell)
{
    float x = 8 + (cell % 6) * 20, y = 8 + (cell / 6) * 20, s = 16;
    glBegin(GL_QUADS);
    glColor3f(1, 0.2f, 0);
    glVertex2f(x, y);
    glColor3f(0, 0, 0.6f);
    glVertex2f(x + s, y);
    glColor3f(1, 0.2f, 0);
    glVertex2f(x + s, y + s);
    glColor3f(0, 0, 0.6f);
    glVertex2f(x, y + s);
    glEnd();
}

int main(int argc, char **argv)
{
    float pos[4] = {0, 1, 1, 0}; /* not the default: a change */
    float ambient[4] = {0.2f, 0.2f, 0.2f, 1}; /* the default */
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    for (int k = 0; k < 27; k++) {
        glTranslatef(0, 0, 0); /* a flush: each cell starts alone */
        clipped_quad();
        switch (k) {
        case 0: break;
        case 1: glDepthFunc(GL_LESS); break;
        case 2: glDepthMask(GL_TRUE); break;
        case 3: glColorMask(1, 1, 1, 1); break;
        case 4: glClearColor(0.25f, 0, 0, 0); break; /* changed, still no flush */
        case 5: glClearDepth(0.5); break;
        case 6: glCullFace(GL_BACK); break;
        case 7: glFrontFace(GL_CCW); break;
        case 8: glProvokingVertex(GL_LAST_VERTEX_CONVENTION); break;
        case 9: glDepthRange(0, 1); break;
        case 10: glViewport(0, 0, 128, 128); break;
        case 11: glShadeModel(GL_SMOOTH); break;
        case 12: glMatrixMode(GL_MODELVIEW); break;
        case 13: glMatrixMode(GL_PROJECTION); glMatrixMode(GL_MODELVIEW); break;
        case 14: glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE); break;
        case 15: glDisable(GL_CULL_FACE); break;
        /* real changes: drawn alone */
        case 16: glDepthFunc(GL_LEQUAL); break;
        case 17: glDepthMask(GL_FALSE); break;
        case 18: glCullFace(GL_FRONT); break;
        case 19: glFrontFace(GL_CW); break;
        case 20: glDepthRange(0, 0.5); break;
        case 21: glViewport(0, 0, 128, 127); break;
        case 22: glColorMaterial(GL_FRONT, GL_DIFFUSE); break;
        case 23: glLightfv(GL_LIGHT0, GL_POSITION, pos); break; /* a new light position */
        /* lighting state set to what it is: no flush */
        case 24: glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0); break;
        case 25: glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient); break;
        case 26: glLightfv(GL_LIGHT0, GL_POSITION, pos); break; /* the position case 23 set */
        }
        inside_quad(k);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
        glDepthRange(0, 1);
        glViewport(0, 0, 128, 128);
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    }
    return scene_end();
}
