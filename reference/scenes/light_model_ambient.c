/* Non-default GL_LIGHT_MODEL_AMBIENT (warm) times different material ambients, plus one dim directional light. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_ortho(1.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    /* start from the default state; only the global ambient and the light differ */
    light_model_ambient(0.55f, 0.3f, 0.11f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.3f, 0.35f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.0f, 0.0f, 0.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 1.0f, 1.0f, 1.0f, 0.0f);
    /* default material ambient (0.2, 0.2, 0.2) on the plane */
    light_grid(-1.0f, -1.0f, 1.0f, 1.0f, -0.8f, 16, 16);
    glPushMatrix();
    glTranslatef(-0.4f, 0.35f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_sphere(0.45f, 24, 12);
    glTranslatef(0.8f, 0.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.2f, 0.9f, 1.0f, 1.0f);
    light_sphere(0.45f, 24, 12);
    glTranslatef(-0.4f, -0.8f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.5f, 0.5f, 0.5f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.1f, 0.6f, 0.2f, 1.0f);
    light_sphere(0.45f, 24, 12);
    glPopMatrix();
    return scene_end();
}
