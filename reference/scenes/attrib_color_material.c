/* glPopAttrib with GL_COLOR_MATERIAL on: after a pop the tracked material is
 * the current colour, when the pop restores the enable itself (GL_ENABLE_BIT)
 * or both the colour and the lighting state (GL_CURRENT_BIT |
 * GL_LIGHTING_BIT, GL_ALL_ATTRIB_BITS). (A pop of only one of the two leaves
 * Mesa's material out of step with the colour: see MESA_FACTS.md.) */
#include "light_common.h"

static void sphere_at(float x, float y)
{
    glPushMatrix();
    glTranslatef(x, y, 0.0f);
    light_sphere(0.3f, 24, 12);
    glPopMatrix();
}

int main(int argc, char **argv)
{
    static const GLfloat green[4] = {0.2f, 0.9f, 0.2f, 1.0f};
    scene_begin(argc, argv, 192, 96);
    light_ortho(1.0f, 2.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.3f, 0.3f, 0.3f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 0.6f, 1.0f, 0.0f);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.9f, 0.2f, 0.2f);
    sphere_at(-1.6f, 0.4f);             /* red */

    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_COLOR_MATERIAL);
    glColor3f(0.9f, 0.9f, 0.1f);        /* not tracked: still red */
    sphere_at(-0.9f, 0.4f);
    glPopAttrib();                      /* tracking again: yellow */
    sphere_at(-0.2f, 0.4f);

    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glColorMaterial(GL_FRONT_AND_BACK, GL_EMISSION);
    glColor3f(0.1f, 0.4f, 0.4f);        /* teal emission over yellow */
    sphere_at(0.5f, 0.4f);
    glPopAttrib();                      /* yellow, no emission */
    sphere_at(1.2f, 0.4f);

    glPushAttrib(GL_CURRENT_BIT | GL_LIGHTING_BIT);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glColor3f(0.2f, 0.3f, 0.9f);        /* diffuse blue, ambient yellow */
    sphere_at(-1.6f, -0.4f);
    glPopAttrib();                      /* yellow */
    sphere_at(-0.9f, -0.4f);

    glPushAttrib(GL_LIGHTING_BIT | GL_ENABLE_BIT);
    glDisable(GL_COLOR_MATERIAL);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, green);
    sphere_at(-0.2f, -0.4f);            /* yellow ambient, green diffuse */
    glPopAttrib();                      /* tracking yellow again */
    sphere_at(0.5f, -0.4f);
    return scene_end();
}
