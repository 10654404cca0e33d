/* Two-sided lighting: a folded strip (zig-zag) and a tilted plane with back faces visible, front/back materials; glFrontFace(GL_CW) on the right half. */
#include "light_common.h"

static void folded_strip(void)
{
    /* five panels folded alternately at +-60 degrees to the x axis, one
     * normal per panel (the panel's front side); seen almost along its
     * length, the -60 panels turn their front and the +60 panels their
     * back towards the eye */
    int k, j;
    float x = -0.55f, z = 0.0f;
    for (k = 0; k < 5; k++) {
        float ang = (k & 1) ? -60.0f : 60.0f;
        float dx = 0.45f * (float)cos(ang * LIGHT_PI / 180.0), dz = 0.45f * (float)sin(ang * LIGHT_PI / 180.0);
        float len = (float)sqrt(dx * dx + dz * dz);
        glBegin(GL_QUAD_STRIP);
        glNormal3f(-dz / len, 0.0f, dx / len);
        for (j = 0; j <= 4; j++) {
            float t = j / 4.0f;
            glVertex3f(x + dx * t, 0.8f, z + dz * t);
            glVertex3f(x + dx * t, -0.8f, z + dz * t);
        }
        glEnd();
        x += dx;
        z += dz;
    }
}

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
        light_frustum(0.45f, 1.0f, 1.0f, 20.0f);
        light_all_black();
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        glFrontFace(c ? GL_CW : GL_CCW);
        light_model_ambient(0.12f, 0.12f, 0.12f, 1.0f);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 0.4f, 1.0f, 0.0f);
        /* a point light left of the strip, for gradients across the panels */
        light_fv(GL_LIGHT1, GL_DIFFUSE, 0.5f, 0.6f, 0.9f, 1.0f);
        light_fv(GL_LIGHT1, GL_SPECULAR, 0.5f, 0.6f, 0.9f, 1.0f);
        light_fv(GL_LIGHT1, GL_POSITION, -0.9f, 0.6f, -2.6f, 1.0f);
        glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1.0f);
        light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 0.9f, 0.2f, 1.0f);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.8f, 0.2f, 1.0f);
        light_mat(GL_FRONT, GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1.0f);
        glMaterialf(GL_FRONT, GL_SHININESS, 10.0f);
        light_mat(GL_BACK, GL_AMBIENT, 0.6f, 0.2f, 0.8f, 1.0f);
        light_mat(GL_BACK, GL_DIFFUSE, 0.6f, 0.2f, 0.8f, 1.0f);
        light_mat(GL_BACK, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        glMaterialf(GL_BACK, GL_SHININESS, 80.0f);
        glTranslatef(0.0f, 0.2f, -3.0f);
        glRotatef(-60.0f, 0.0f, 1.0f, 0.0f);
        folded_strip();
        /* a plane tilted away: CCW seen from its back, so its back face shows */
        glLoadIdentity();
        glTranslatef(0.0f, -1.05f, -3.5f);
        glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(180.0f, 0.0f, 1.0f, 0.0f);
        light_grid(-1.2f, -0.6f, 1.2f, 0.6f, 0.0f, 16, 8);
    }
    return scene_end();
}
