/* A lit scene of several objects, each drawn inside
 * glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT | ...) with its own lights,
 * materials, shade model, depth func and cull face; the objects drawn after
 * each glPopAttrib use the scene's base state again, so a group that is not
 * restored, or restored wrong, changes their pixels. */
#include "light_common.h"

/* The base state every object after a pop must see. */
static void base_state(void)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.1f, 0.1f, 0.1f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.6f, 0.6f, 0.6f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.6f, 0.6f, 0.6f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
}

static void at(float x, float y, float z)
{
    glPopMatrix();
    glPushMatrix();
    glTranslatef(x, y, z);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 128);
    light_frustum(0.6f, 1.5f, 2.0f, 9.0f);
    base_state();
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
    glPushMatrix();

    /* 1: its own red spot light from the left, no LIGHT0, flat, shiny. */
    at(-1.35f, 0.45f, 0.0f);
    glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT);
    glDisable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 1.0f, 0.2f, 0.1f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPECULAR, 1.0f, 1.0f, 0.6f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, -2.0f, 1.0f, 1.0f, 1.0f);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 40.0f);
    light_fv(GL_LIGHT1, GL_SPOT_DIRECTION, 1.5f, -0.5f, -1.0f, 0.0f);
    glShadeModel(GL_FLAT);
    light_mat(GL_FRONT, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
    light_sphere(0.5f, 24, 12);
    glPopAttrib();

    /* 2: base state. */
    at(-0.45f, 0.45f, 0.0f);
    light_sphere(0.4f, 24, 12);

    /* 3: an open tube, clockwise front faces culled as back faces, so only
     * its inside shows; two-sided lighting, green and yellow materials, a
     * second light. */
    at(0.45f, 0.2f, 0.0f);
    glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT | GL_POLYGON_BIT);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glEnable(GL_LIGHT2);
    light_fv(GL_LIGHT2, GL_DIFFUSE, 0.2f, 0.3f, 1.0f, 1.0f);
    light_fv(GL_LIGHT2, GL_POSITION, 1.0f, 0.5f, 0.5f, 0.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.9f, 0.3f, 1.0f);
    light_mat(GL_BACK, GL_DIFFUSE, 0.9f, 0.9f, 0.2f, 1.0f);
    light_tube(0.35f, -0.4f, 0.4f, 0.0f, 360.0f, 24, 4);
    glPopAttrib();

    /* 4: base state but culling on: the base glCullFace(GL_BACK) and
     * glFrontFace(GL_CCW) must be back, so only the outside is drawn. */
    at(1.35f, 0.2f, 0.0f);
    glPushAttrib(GL_ENABLE_BIT);
    glEnable(GL_CULL_FACE);
    light_tube(0.3f, -0.4f, 0.4f, 20.0f, 300.0f, 24, 4);
    glPopAttrib();

    /* 5: drawn behind sphere 2 with GL_ALWAYS: over it; a lit emission. */
    at(-0.7f, -0.45f, -0.8f);
    glPushAttrib(GL_DEPTH_BUFFER_BIT | GL_LIGHTING_BIT);
    glDepthFunc(GL_ALWAYS);
    light_mat(GL_FRONT, GL_EMISSION, 0.2f, 0.0f, 0.3f, 1.0f);
    light_model_ambient(0.4f, 0.3f, 0.1f, 1.0f);
    light_sphere(0.45f, 24, 12);
    glPopAttrib();

    /* 6: behind 5 with GL_LESS again: hidden where 5 is nearer. */
    at(-0.45f, -0.5f, -1.2f);
    light_sphere(0.5f, 24, 12);

    /* 7: depth writes off, lighting off, a constant colour; then a lit
     * sphere through it, which must be depth-tested against 6 only. */
    at(0.6f, -0.55f, 0.2f);
    glPushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_LIGHTING);
    glDepthMask(GL_FALSE);
    glColor3f(0.3f, 0.6f, 0.9f);
    light_grid(-0.6f, -0.3f, 0.6f, 0.3f, 0.0f, 6, 3);
    glPopAttrib();
    at(0.6f, -0.55f, 0.0f);
    light_sphere(0.3f, 24, 12);

    glPopMatrix();
    return scene_end();
}
