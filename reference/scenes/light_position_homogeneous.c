/* Positional lights given with w != 1 ((x,y,z,1), (2x,2y,2z,2), (x/2,y/2,z/2,1/2)) with attenuation, and a long w = 0 direction. */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const float w[3] = { 1.0f, 2.0f, 0.5f };
    int c;
    scene_begin(argc, argv, 256, 256);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.05f, 0.05f, 0.05f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 1.0f, 0.9f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        if (c < 3) {
            float k = w[c];
            light_fv(GL_LIGHT0, GL_POSITION, -0.4f * k, 0.3f * k, 0.5f * k, k);
            glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 1.5f);
        } else {
            light_fv(GL_LIGHT0, GL_POSITION, -40.0f, 30.0f, 50.0f, 0.0f);
            glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.0f);
        }
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.7f, 0.7f, 0.8f, 1.0f);
        light_mat(GL_FRONT, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, -0.5f, 40, 40);
        glPushMatrix();
        glTranslatef(0.3f, -0.25f, 0.0f);
        light_sphere(0.4f, 32, 16);
        glPopMatrix();
    }
    return scene_end();
}
