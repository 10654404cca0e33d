/* Emission only (no light, zero global ambient): flat colours; alpha comes from the diffuse alpha, not the emission. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_ortho(1.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    light_all_black();
    light_mat(GL_FRONT, GL_EMISSION, 0.2f, 0.3f, 0.5f, 0.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.0f, 0.0f, 0.0f, 0.7f);
    light_grid(-1.0f, -1.0f, 1.0f, 1.0f, -0.8f, 8, 8);
    glPushMatrix();
    glTranslatef(-0.3f, 0.2f, 0.0f);
    light_mat(GL_FRONT, GL_EMISSION, 0.9f, 0.5f, 0.1f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.0f, 0.0f, 0.0f, 1.0f);
    light_sphere(0.5f, 24, 12);
    glTranslatef(0.6f, -0.4f, 0.1f);
    light_mat(GL_FRONT, GL_EMISSION, 0.1f, 0.8f, 0.3f, 0.5f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 0.25f);
    light_sphere(0.45f, 24, 12);
    glPopMatrix();
    return scene_end();
}
