/* Colours above 1: light 3x, material 2x, global ambient 1.5, emission 1.5, glColor up to 2.5 through glColorMaterial; clamped at the vertex. */
#include "light_common.h"

int main(int argc, char **argv)
{
    int c, j;
    scene_begin(argc, argv, 256, 256);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        light_all_black();
        light_model_ambient(0.05f, 0.05f, 0.05f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.5f, 1.0f, 0.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.4f, 0.4f, 0.4f, 1.0f);
        light_mat(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
        switch (c) {
        case 0: /* over-bright light */
            light_fv(GL_LIGHT0, GL_DIFFUSE, 3.0f, 1.5f, 0.4f, 1.0f);
            light_fv(GL_LIGHT0, GL_SPECULAR, 2.0f, 2.0f, 2.0f, 1.0f);
            break;
        case 1: /* over-bright material */
            light_mat(GL_FRONT, GL_DIFFUSE, 2.0f, 0.5f, 1.2f, 1.0f);
            light_mat(GL_FRONT, GL_SPECULAR, 3.0f, 3.0f, 0.0f, 1.0f);
            break;
        case 2: /* global ambient and emission above 1 (one channel each) */
            light_model_ambient(1.5f, 0.11f, 0.11f, 1.0f);
            light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.2f, 0.2f, 1.0f);
            light_mat(GL_FRONT, GL_EMISSION, 0.0f, 0.0f, 1.5f, 1.0f);
            break;
        case 3: /* glColor above 1 fed to the diffuse material */
            glColorMaterial(GL_FRONT, GL_DIFFUSE);
            glEnable(GL_COLOR_MATERIAL);
            break;
        }
        if (c == 3) {
            /* sphere bands with glColor up to 2.5 */
            for (j = 0; j < 16; j++) {
                int i;
                double t0 = LIGHT_PI * j / 16, t1 = LIGHT_PI * (j + 1) / 16;
                glBegin(GL_QUAD_STRIP);
                for (i = 0; i <= 32; i++) {
                    double p = 2.0 * LIGHT_PI * (i % 32) / 32;
                    float x0 = (float)(sin(t0) * cos(p)), y0 = (float)cos(t0), z0 = (float)(-sin(t0) * sin(p));
                    float x1 = (float)(sin(t1) * cos(p)), y1 = (float)cos(t1), z1 = (float)(-sin(t1) * sin(p));
                    glColor3f(2.5f * i / 32.0f, 0.2f + 0.1f * j, 1.0f);
                    glNormal3f(x0, y0, z0);
                    glVertex3f(0.9f * x0, 0.9f * y0, 0.9f * z0);
                    glNormal3f(x1, y1, z1);
                    glVertex3f(0.9f * x1, 0.9f * y1, 0.9f * z1);
                }
                glEnd();
            }
            glDisable(GL_COLOR_MATERIAL);
        } else {
            light_sphere(0.9f, 40, 20);
        }
    }
    return scene_end();
}
