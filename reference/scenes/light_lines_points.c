/* Lighting on GL_LINES, GL_LINE_STRIP and GL_POINTS with per-vertex normals (a wire sphere and a point sphere). */
#include "light_common.h"

int main(int argc, char **argv)
{
    int i, j;
    scene_begin(argc, argv, 128, 128);
    light_ortho(1.05f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);

    /* left: latitude circles as line strips, meridians as GL_LINES */
    glPushMatrix();
    glTranslatef(-0.5f, 0.45f, 0.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.5f, 0.2f, 1.0f);
    for (i = 1; i < 8; i++) {
        glBegin(GL_LINE_STRIP);
        for (j = 0; j <= 24; j++)
            light_sphere_vertex(0.45f, i, j, 24, 8);
        glEnd();
    }
    glBegin(GL_LINES);
    for (j = 0; j < 24; j++)
        for (i = 0; i < 8; i++) {
            light_sphere_vertex(0.45f, i, j, 24, 8);
            light_sphere_vertex(0.45f, i + 1, j, 24, 8);
        }
    glEnd();
    glPopMatrix();

    /* right: a point sphere */
    glPushMatrix();
    glTranslatef(0.5f, 0.45f, 0.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.6f, 0.9f, 1.0f);
    glBegin(GL_POINTS);
    for (i = 1; i < 16; i++)
        for (j = 0; j < 32; j++)
            light_sphere_vertex(0.45f, i, j, 32, 16);
    glEnd();
    glPopMatrix();

    /* bottom: a lit zig-zag line strip with normals turning */
    light_mat(GL_FRONT, GL_DIFFUSE, 0.5f, 0.9f, 0.4f, 1.0f);
    glBegin(GL_LINE_STRIP);
    for (j = 0; j <= 40; j++) {
        double a = LIGHT_PI * j / 40.0;
        glNormal3f((float)-cos(a), 0.3f, (float)sin(a));
        glVertex3f(-0.95f + 1.9f * j / 40.0f, (j & 1) ? -0.25f : -0.9f, 0.0f);
    }
    glEnd();
    return scene_end();
}
