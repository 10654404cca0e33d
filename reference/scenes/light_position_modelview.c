/* Light positions and spot direction set under different modelviews (rotate/translate, even in GL_PROJECTION mode), then the modelview changes before drawing. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_frustum(0.5f, 1.0f, 1.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHT2);
    light_all_black();
    light_model_ambient(0.12f, 0.12f, 0.12f, 1.0f);

    /* light 0: point light at (0, 0, 1.2) in a frame rotated 50 degrees
     * about y and moved to the scene centre -> lands front right */
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(50.0f, 0.0f, 1.0f, 0.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.6f, 0.3f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.0f, 0.0f, 1.2f, 1.0f);

    /* light 1: spot; position and direction set under a rotation about x
     * (the direction is transformed by the upper 3x3 only) */
    glLoadIdentity();
    glTranslatef(-0.6f, 0.8f, -2.4f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.3f, 0.6f, 1.0f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, 0.0f, 0.0f, 0.0f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPOT_DIRECTION, 0.0f, 0.0f, -1.0f, 0.0f);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 25.0f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 4.0f);

    /* light 2: directional, set while GL_PROJECTION is the current matrix
     * mode with a scaled projection loaded; the modelview (a rotation
     * about z) still transforms it */
    glLoadIdentity();
    glRotatef(-80.0f, 0.0f, 0.0f, 1.0f);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glScalef(3.0f, -2.0f, 0.5f);
    light_fv(GL_LIGHT2, GL_DIFFUSE, 0.2f, 0.5f, 0.2f, 1.0f);
    light_fv(GL_LIGHT2, GL_POSITION, 0.0f, 1.0f, 0.3f, 0.0f);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);

    /* now draw under an unrelated modelview */
    glLoadIdentity();
    glTranslatef(0.0f, -0.2f, -3.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_floor(-1.6f, -1.6f, 1.6f, 1.6f, -0.6f, 48, 48);
    light_sphere(0.5f, 32, 16);
    return scene_end();
}
