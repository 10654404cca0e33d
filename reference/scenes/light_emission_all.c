/* Emission + global ambient + light ambient + diffuse + specular from two lights, summing past 1 (clamped). */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_frustum(0.5f, 1.0f, 1.0f, 10.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_all_black();
    light_model_ambient(0.11f, 0.11f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_AMBIENT, 0.2f, 0.1f, 0.05f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.7f, 0.5f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -1.0f, 1.0f, 1.0f, 0.0f);
    light_fv(GL_LIGHT1, GL_AMBIENT, 0.0f, 0.05f, 0.1f, 1.0f);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.2f, 0.4f, 0.9f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPECULAR, 0.5f, 0.5f, 1.0f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, 1.5f, -0.5f, -1.5f, 1.0f);
    light_mat(GL_FRONT, GL_EMISSION, 0.25f, 0.05f, 0.0f, 1.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.8f, 0.6f, 0.6f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.7f, 0.4f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 25.0f);
    glTranslatef(0.0f, 0.0f, -3.0f);
    light_sphere(1.1f, 40, 24);
    return scene_end();
}
