/* Depth-tested lit geometry: three intersecting shiny spheres (glFrustum), the intersection curves decided per pixel. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_frustum(0.6f, 1.0f, 2.0f, 8.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.12f, 0.12f, 0.12f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.85f, 0.85f, 0.85f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glTranslatef(0.0f, 0.0f, -4.5f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);

    glPushMatrix();
    glTranslatef(-0.45f, 0.1f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.3f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.3f, 0.2f, 1.0f);
    light_sphere(0.8f, 40, 20);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.5f, 0.0f, 0.2f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.2f, 0.7f, 0.9f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.7f, 0.9f, 1.0f);
    light_sphere(0.7f, 40, 20);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.0f, -0.6f, 0.3f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.8f, 0.8f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.8f, 0.2f, 1.0f);
    light_sphere(0.6f, 40, 20);
    glPopMatrix();
    return scene_end();
}
