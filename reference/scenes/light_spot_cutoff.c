/* Spotlight cutoffs 5, 30, 60, 90, 180 (no spot) and a grazing 15 (cells) on a finely tessellated plane: the cone edge. */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const float cut[6] = { 5.0f, 30.0f, 60.0f, 90.0f, 180.0f, 15.0f };
    static const float pos[6][3] = {
        { 0.0f, 0.0f, 2.5f }, { -0.5f, 0.0f, 1.0f }, { -0.8f, -0.3f, 0.6f },
        { -0.3f, 0.2f, 0.4f }, { 0.0f, 0.0f, 0.6f }, { -1.0f, -0.8f, 0.25f },
    };
    static const float dir[6][3] = {
        { 0.0f, 0.0f, -1.0f }, { 0.5f, 0.0f, -1.0f }, { 1.0f, 0.4f, -1.0f },
        { 1.0f, 0.3f, -0.2f }, { 1.0f, 0.0f, 0.0f }, { 1.0f, 0.7f, -0.3f },
    };
    int c;
    scene_begin(argc, argv, 384, 256);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 6; c++) {
        light_cell(c, 3, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.11f, 0.08f, 0.08f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 1.0f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, pos[c][0], pos[c][1], pos[c][2], 1.0f);
        light_fv(GL_LIGHT0, GL_SPOT_DIRECTION, dir[c][0], dir[c][1], dir[c][2], 0.0f);
        glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cut[c]);
        glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 1.0f, 1.0f, 1.0f, 1.0f);
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, 0.0f, 64, 64);
    }
    return scene_end();
}
