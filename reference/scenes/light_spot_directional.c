/* Spot cutoff / exponent and attenuation set on directional lights (w = 0): spot off-axis, spot pointing away, attenuation; and a positional spot. */
#include "light_common.h"

int main(int argc, char **argv)
{
    int c;
    scene_begin(argc, argv, 256, 256);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
        light_fv(GL_LIGHT0, GL_AMBIENT, 0.1f, 0.0f, 0.2f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.9f, 0.7f, 1.0f);
        /* cells 0, 1, 2: w = 0; cell 3: a spot on a positional light there */
        light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.3f, 1.0f, c == 3 ? 1.0f : 0.0f);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0.0f);
        glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1.0f);
        glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.0f);
        if (c == 0) {
            /* spot axis 23 degrees off the light direction: inside the
             * cutoff, weakened by the exponent (the GL formula) */
            light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.0f, 0.0f, -1.0f, 0.0f);
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30.0f);
            glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 8.0f);
        } else if (c == 3) {
            /* narrow spot aimed at the centre */
            light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.3f, -0.3f, -1.0f, 0.0f);
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 20.0f);
            glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 8.0f);
        } else if (c == 1) {
            /* spot aimed away from everything */
            light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.0f, 0.0f, 1.0f, 0.0f);
            glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 10.0f);
        } else {
            glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.5f);
            glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 4.0f);
        }
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, -0.6f, 48, 48);
        glPushMatrix();
        glTranslatef(0.2f, -0.2f, 0.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.3f, 0.6f, 0.9f, 1.0f);
        light_sphere(0.45f, 32, 16);
        glPopMatrix();
    }
    return scene_end();
}
