/* glPushAttrib and glPopAttrib compiled into display lists (§5.4): a list
 * that pushes, changes lighting, colour, depth and polygon state, draws, and
 * pops; a push in one list popped by another; GL_COMPILE_AND_EXECUTE of a
 * push/pop pair; and a glCallList between a push and a pop. Lit spheres show
 * the state each draw ran with. */
#include "light_common.h"

enum { SPHERE = 1, RED_FLAT, PUSH_GREEN, POP, BOTH, CALLS };

int main(int argc, char **argv)
{
    static const GLfloat red[4] = {0.9f, 0.2f, 0.1f, 1}, green[4] = {0.2f, 0.8f, 0.3f, 1};
    scene_begin(argc, argv, 200, 150);
    light_frustum(0.5f, 200.0f / 150.0f, 2.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.7f, 1.0f, 0.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.5f, 0.5f, 0.8f, 1.0f);

    glNewList(SPHERE, GL_COMPILE);
    light_sphere(0.6f, 18, 12);
    glEndList();
    glNewList(RED_FLAT, GL_COMPILE);
    glPushAttrib(GL_LIGHTING_BIT | GL_POLYGON_BIT);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
    glShadeModel(GL_FLAT);
    glCallList(SPHERE);
    glPopAttrib();
    glEndList();
    glNewList(PUSH_GREEN, GL_COMPILE); /* popped by list POP */
    glPushAttrib(GL_LIGHTING_BIT | GL_CURRENT_BIT | GL_ENABLE_BIT);
    glDisable(GL_LIGHTING);
    glColor3fv(green);
    glEndList();
    glNewList(POP, GL_COMPILE);
    glPopAttrib();
    glEndList();
    glNewList(BOTH, GL_COMPILE_AND_EXECUTE); /* runs now, changes nothing after */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glDisable(GL_DEPTH_TEST);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glPopAttrib();
    glEndList();
    glNewList(CALLS, GL_COMPILE);
    glPushAttrib(GL_POLYGON_BIT | GL_ENABLE_BIT | GL_LIGHTING_BIT);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT); /* the inside of the far half */
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glCallList(SPHERE);
    glPopAttrib();
    glTranslatef(0.0f, 0.0f, -1.0f);
    glCallList(SPHERE); /* whole and one-sided again */
    glEndList();

    scene_clear();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(-1.5f, 0.8f, -8.0f);
    glCallList(RED_FLAT);
    glTranslatef(1.5f, 0.0f, 0.0f);
    glCallList(SPHERE); /* the default material again, smooth */
    glTranslatef(1.5f, 0.0f, 0.0f);
    glCallList(PUSH_GREEN);
    glCallList(SPHERE); /* unlit green */
    glCallList(POP);
    glTranslatef(-3.0f, -1.6f, 0.0f);
    glCallList(SPHERE); /* lit again */
    glTranslatef(1.5f, 0.0f, 0.0f);
    glCallList(CALLS);
    glTranslatef(1.5f, 0.0f, 0.3f);
    glCallList(BOTH);
    glCallList(SPHERE);
    return scene_end();
}
