/* Normals not unit length without GL_NORMALIZE: length 1, 2.5 (diffuse and highlight saturate), 0.4 (dim); 2.5 with GL_NORMALIZE. */
#include "light_common.h"

static void sphere_scaled_normals(float r, float nlen, int slices, int stacks)
{
    int i, j;
    for (i = 0; i < stacks; i++) {
        double t0 = LIGHT_PI * i / stacks, t1 = LIGHT_PI * (i + 1) / stacks;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= slices; j++) {
            double p = 2.0 * LIGHT_PI * (j % slices) / slices;
            float x0 = (float)(sin(t0) * cos(p)), y0 = (float)cos(t0), z0 = (float)(-sin(t0) * sin(p));
            float x1 = (float)(sin(t1) * cos(p)), y1 = (float)cos(t1), z1 = (float)(-sin(t1) * sin(p));
            glNormal3f(nlen * x0, nlen * y0, nlen * z0);
            glVertex3f(r * x0, r * y0, r * z0);
            glNormal3f(nlen * x1, nlen * y1, nlen * z1);
            glVertex3f(r * x1, r * y1, r * z1);
        }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    static const float nlen[4] = { 1.0f, 2.5f, 0.4f, 2.5f };
    int c;
    scene_begin(argc, argv, 256, 256);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 128, 128);
        light_ortho(1.05f, 1.0f);
        light_all_black();
        light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, -0.5f, 0.5f, 1.0f, 0.0f);
        light_fv(GL_LIGHT1, GL_DIFFUSE, 0.3f, 0.2f, 0.1f, 1.0f);
        light_fv(GL_LIGHT1, GL_POSITION, 1.5f, -1.0f, 1.5f, 1.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.4f, 0.6f, 0.8f, 1.0f);
        light_mat(GL_FRONT, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
        if (c == 3)
            glEnable(GL_NORMALIZE);
        else
            glDisable(GL_NORMALIZE);
        sphere_scaled_normals(1.0f, nlen[c], 40, 20);
    }
    return scene_end();
}
