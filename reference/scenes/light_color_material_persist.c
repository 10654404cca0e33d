/* glColorMaterial state edges: after glDisable(GL_COLOR_MATERIAL) the material keeps the last tracked colour; glColor then no longer changes it. */
#include "light_common.h"

int main(int argc, char **argv)
{
    int j;
    scene_begin(argc, argv, 128, 128);
    light_ortho(1.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.2f, 0.2f, 0.2f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.5f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.5f, 0.5f, 0.5f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1.0f);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    /* a band across the top with a colour ramp; the last colour is pink */
    glNormal3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_QUAD_STRIP);
    for (j = 0; j <= 16; j++) {
        float t = j / 16.0f;
        glColor3f(0.2f + 0.7f * t, 0.8f - 0.5f * t, 0.3f + 0.3f * t);
        glVertex3f(-1.0f + 2.0f * t, 1.0f, 0.0f);
        glVertex3f(-1.0f + 2.0f * t, 0.55f, 0.0f);
    }
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    /* ignored by lighting now: the material stays (0.9, 0.3, 0.6) */
    glColor3f(0.1f, 0.9f, 0.1f);
    glPushMatrix();
    glTranslatef(-0.45f, -0.25f, 0.0f);
    light_sphere(0.45f, 24, 12);
    glPopMatrix();
    /* tracking again, GL_DIFFUSE only: the ambient keeps the pink */
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.2f, 0.4f, 1.0f);
    glPushMatrix();
    glTranslatef(0.45f, -0.25f, 0.0f);
    light_sphere(0.45f, 24, 12);
    glPopMatrix();
    return scene_end();
}
