/* Uniformly scaled modelview (x0.5 top row, x2 bottom row): no normal fix-up, GL_NORMALIZE, GL_RESCALE_NORMAL (columns). */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const float scale[2] = { 0.5f, 2.0f };
    int c;
    scene_begin(argc, argv, 288, 192);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 6; c++) {
        float s = scale[c / 3];
        light_cell(c, 3, 2, 96, 96);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.7f, 0.7f, 0.7f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.5f, 0.6f, 1.0f, 0.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.3f, 0.6f, 0.4f, 1.0f);
        light_mat(GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
        glDisable(GL_NORMALIZE);
        glDisable(GL_RESCALE_NORMAL);
        if (c % 3 == 1)
            glEnable(GL_NORMALIZE);
        else if (c % 3 == 2)
            glEnable(GL_RESCALE_NORMAL);
        glScalef(s, s, s);
        light_sphere(0.85f / s, 32, 16);
    }
    return scene_end();
}
