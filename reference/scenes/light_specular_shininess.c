/* Specular highlight with GL_SHININESS 0, 1, 10, 128, 3.5, and 0 under two-sided lighting with back shininess 50; white specular. */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const float shin[6] = { 0.0f, 1.0f, 10.0f, 128.0f, 3.5f, 0.0f };
    int c;
    scene_begin(argc, argv, 384, 256);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 6; c++) {
        light_cell(c, 3, 2, 128, 128);
        light_ortho(1.05f, 1.0f);
        light_all_black();
        light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.7f, 0.7f, 0.7f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.6f, 0.6f, 1.0f, 0.0f);
        light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.2f, 0.3f, 0.6f, 1.0f);
        light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.1f, 0.2f, 0.5f, 1.0f);
        light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, shin[c]);
        /* last cell: a non-zero back shininess makes the front's 0 go
         * through the general specular path */
        glMaterialf(GL_BACK, GL_SHININESS, c == 5 ? 50.0f : 0.0f);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, c == 5 ? GL_TRUE : GL_FALSE);
        light_sphere(1.0f, 48, 32);
    }
    return scene_end();
}
