/* Negative light and material components: a "dark" light subtracting colour, negative ambient terms; clamped to [0,1] at the vertex. */
#include "light_common.h"

int main(int argc, char **argv)
{
    int c;
    scene_begin(argc, argv, 256, 128);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    for (c = 0; c < 2; c++) {
        light_cell(c, 2, 1, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.3f, 0.3f, 0.3f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 0.9f, 0.8f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.5f, 1.0f, 0.0f);
        /* the dark light, from the right */
        light_fv(GL_LIGHT1, GL_AMBIENT, -0.1f, 0.0f, -0.05f, 1.0f);
        light_fv(GL_LIGHT1, GL_DIFFUSE, -0.9f, -0.2f, 0.3f, 1.0f);
        light_fv(GL_LIGHT1, GL_SPECULAR, -1.0f, 0.0f, -1.0f, 1.0f);
        light_fv(GL_LIGHT1, GL_POSITION, 1.0f, -0.2f, 0.6f, 0.0f);
        if (c == 0) {
            light_mat(GL_FRONT, GL_AMBIENT, 0.5f, 0.5f, 0.5f, 1.0f);
            light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.6f, 0.4f, 1.0f);
            light_mat(GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1.0f);
        } else {
            /* negative material terms and a negative global ambient */
            light_model_ambient(-0.2f, 0.4f, -0.1f, 1.0f);
            light_mat(GL_FRONT, GL_EMISSION, 0.1f, -0.3f, 0.2f, 1.0f);
            light_mat(GL_FRONT, GL_AMBIENT, 0.5f, 0.5f, 0.5f, 1.0f);
            light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, -0.4f, 0.6f, 1.0f);
            light_mat(GL_FRONT, GL_SPECULAR, -0.5f, 0.9f, 0.9f, 1.0f);
        }
        glMaterialf(GL_FRONT, GL_SHININESS, 15.0f);
        light_grid(-1.0f, -1.0f, 1.0f, 1.0f, -0.9f, 16, 16);
        light_sphere(0.85f, 40, 20);
    }
    return scene_end();
}
