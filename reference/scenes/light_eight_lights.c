/* All 8 lights at once, mixed kinds (directional, point, spot) and colours, on a floor and three spheres (glFrustum). */
#include "light_common.h"

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 192, 192);
    light_frustum(0.55f, 1.0f, 1.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    light_all_black();
    light_model_ambient(0.05f, 0.05f, 0.05f, 1.0f);
    for (i = 0; i < 8; i++)
        glEnable(GL_LIGHT0 + i);
    /* camera: looking 15 degrees down; lights are set under it */
    glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
    /* 0: directional, red */
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.1f, 0.1f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -1.0f, 1.0f, 0.5f, 0.0f);
    /* 1: point, green, linear attenuation */
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.1f, 0.8f, 0.1f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPECULAR, 0.3f, 1.0f, 0.3f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, 1.3f, 0.3f, -2.3f, 1.0f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.8f);
    /* 2: spot, blue, straight down */
    light_fv(GL_LIGHT2, GL_DIFFUSE, 0.2f, 0.3f, 1.0f, 1.0f);
    light_fv(GL_LIGHT2, GL_POSITION, 0.0f, 2.0f, -3.6f, 1.0f);
    light_fv(GL_LIGHT2, GL_SPOT_DIRECTION, 0.0f, -1.0f, 0.0f, 0.0f);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 25.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 5.0f);
    /* 3: directional, dim white, from below right */
    light_fv(GL_LIGHT3, GL_AMBIENT, 0.05f, 0.05f, 0.08f, 1.0f);
    light_fv(GL_LIGHT3, GL_DIFFUSE, 0.2f, 0.2f, 0.2f, 1.0f);
    light_fv(GL_LIGHT3, GL_POSITION, 0.5f, -0.3f, 0.5f, 0.0f);
    /* 4: point, magenta, quadratic attenuation */
    light_fv(GL_LIGHT4, GL_DIFFUSE, 0.8f, 0.1f, 0.7f, 1.0f);
    light_fv(GL_LIGHT4, GL_POSITION, -1.6f, -0.4f, -2.4f, 1.0f);
    glLightf(GL_LIGHT4, GL_CONSTANT_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT4, GL_QUADRATIC_ATTENUATION, 0.6f);
    /* 5: spot, yellow, narrow, with specular */
    light_fv(GL_LIGHT5, GL_DIFFUSE, 0.9f, 0.8f, 0.1f, 1.0f);
    light_fv(GL_LIGHT5, GL_SPECULAR, 1.0f, 1.0f, 0.5f, 1.0f);
    light_fv(GL_LIGHT5, GL_POSITION, 1.5f, 1.5f, -2.0f, 1.0f);
    light_fv(GL_LIGHT5, GL_SPOT_DIRECTION, -1.2f, -1.7f, -1.4f, 0.0f);
    glLightf(GL_LIGHT5, GL_SPOT_CUTOFF, 20.0f);
    glLightf(GL_LIGHT5, GL_SPOT_EXPONENT, 10.0f);
    /* 6: point, cyan, constant attenuation */
    light_fv(GL_LIGHT6, GL_DIFFUSE, 0.1f, 0.6f, 0.6f, 1.0f);
    light_fv(GL_LIGHT6, GL_POSITION, 0.0f, -0.3f, -1.6f, 1.0f);
    glLightf(GL_LIGHT6, GL_CONSTANT_ATTENUATION, 2.0f);
    /* 7: wide spot, orange, white specular */
    light_fv(GL_LIGHT7, GL_DIFFUSE, 0.9f, 0.4f, 0.1f, 1.0f);
    light_fv(GL_LIGHT7, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT7, GL_POSITION, -2.2f, 1.0f, -4.2f, 1.0f);
    light_fv(GL_LIGHT7, GL_SPOT_DIRECTION, 1.0f, -0.6f, 0.4f, 0.0f);
    glLightf(GL_LIGHT7, GL_SPOT_CUTOFF, 60.0f);
    glLightf(GL_LIGHT7, GL_SPOT_EXPONENT, 1.0f);

    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.45f, 0.45f, 0.45f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    light_floor(-3.0f, -7.0f, 3.0f, -1.0f, -1.0f, 48, 48);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    for (i = 0; i < 3; i++) {
        glPushMatrix();
        glTranslatef(-1.2f + 1.2f * i, -0.45f + 0.1f * i, -3.6f + 0.3f * (i & 1));
        light_sphere(0.55f, 32, 16);
        glPopMatrix();
    }
    return scene_end();
}
