/* Ambient only: global ambient; a directional light's ambient; a point light's ambient (attenuated); a spot's ambient (cone). */
#include "light_common.h"

int main(int argc, char **argv)
{
    int c;
    scene_begin(argc, argv, 192, 192);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 96, 96);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        glDisable(GL_LIGHT0);
        if (c == 0) {
            light_model_ambient(0.25f, 0.25f, 0.25f, 1.0f);
        } else {
            glEnable(GL_LIGHT0);
            light_fv(GL_LIGHT0, GL_AMBIENT, 0.3f, 0.5f, 0.7f, 1.0f);
            if (c == 1) {
                light_fv(GL_LIGHT0, GL_POSITION, 0.0f, 0.0f, 1.0f, 0.0f);
            } else {
                light_fv(GL_LIGHT0, GL_POSITION, -0.5f, -0.4f, 0.3f, 1.0f);
                if (c == 2) {
                    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.2f);
                    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1.5f);
                } else {
                    light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.5f, 0.6f, -0.5f, 0.0f);
                    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35.0f);
                    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 3.0f);
                }
            }
        }
        light_mat(GL_FRONT, GL_AMBIENT, 0.6f, 0.6f, 0.9f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f); /* no diffuse light: unused */
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, -0.5f, 32, 32);
        glPushMatrix();
        glTranslatef(0.35f, 0.35f, 0.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 0.7f, 0.4f, 1.0f);
        light_sphere(0.5f, 24, 12);
        glPopMatrix();
        glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1.0f);
        glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.0f);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0.0f);
    }
    return scene_end();
}
