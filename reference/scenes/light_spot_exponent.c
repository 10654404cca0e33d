/* Spotlight exponents 0, 2, 20 and 128 (cells), cutoff 50, on a finely tessellated plane. */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const float expo[4] = { 0.0f, 2.0f, 20.0f, 128.0f };
    int c;
    scene_begin(argc, argv, 256, 256);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.08f, 0.08f, 0.11f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 1.0f, 0.9f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.3f, -0.2f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, 0.3f, 0.2f, -1.0f, 0.0f);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 50.0f);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, expo[c]);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f, 64, 64);
    }
    return scene_end();
}
