/* glLightfv(GL_SPOT_DIRECTION) with non-unit vectors (lengths 1, 4, 0.25: the same cone) and a unit vector under a scaled modelview (upper 3x3 applied). */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const float len[4] = { 1.0f, 4.0f, 0.25f, 1.0f };
    int c;
    scene_begin(argc, argv, 256, 256);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 4; c++) {
        float k = len[c];
        light_cell(c, 2, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.9f, 0.6f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.3f, 0.8f, 1.0f);
        if (c == 3) {
            /* unit vector under glScalef(3, 0.5, 2): the eye-space direction
             * is neither unit length nor parallel to the given one */
            glPushMatrix();
            glScalef(3.0f, 0.5f, 2.0f);
            light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.3f, -0.5f, -0.81f, 0.0f);
            glPopMatrix();
        } else {
            light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.5f * k, -0.3f * k, -0.8f * k, 0.0f);
        }
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35.0f);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 6.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f, 64, 64);
    }
    return scene_end();
}
