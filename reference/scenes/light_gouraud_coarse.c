/* Gouraud shading on coarse hand-built spheres (6x4, 8x5, 12x6 latitude/longitude bands) with a specular highlight. */
#include "light_common.h"

int main(int argc, char **argv)
{
    static const int res[3][2] = { { 6, 4 }, { 8, 5 }, { 12, 6 } };
    int c;
    scene_begin(argc, argv, 384, 128);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.4f, 0.6f, 0.9f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.3f, 0.5f, 0.9f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 25.0f);
    for (c = 0; c < 3; c++) {
        light_cell(c, 3, 1, 128, 128);
        light_frustum(0.35f, 1.0f, 1.0f, 10.0f);
        glTranslatef(0.0f, 0.0f, -3.0f);
        glRotatef(15.0f + 10.0f * c, 1.0f, 0.0f, 0.0f);
        glRotatef(10.0f, 0.0f, 1.0f, 0.0f);
        light_sphere(0.95f, res[c][0], res[c][1]);
    }
    return scene_end();
}
