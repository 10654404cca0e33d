/* "Lighting lecture": sun (directional), lamp (attenuated point) and spotlight together on a floor and a few objects, 256x256, depth tested. */
#include "light_common.h"
#include <GL/glu.h>

static void box(float sx, float sy, float sz)
{
    static const float n[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    int f, i, j;
    for (f = 0; f < 6; f++) {
        /* two tangent axes u, v with u x v = n */
        float u[3], v[3];
        int a = f / 2;
        float sgn = n[f][a];
        int b = (a + 1) % 3, c = (a + 2) % 3;
        u[0] = u[1] = u[2] = 0.0f;
        v[0] = v[1] = v[2] = 0.0f;
        u[b] = 1.0f;
        v[c] = sgn;
        glNormal3fv(n[f]);
        for (j = 0; j < 6; j++) {
            glBegin(GL_QUAD_STRIP);
            for (i = 0; i <= 6; i++) {
                int k;
                for (k = 1; k >= 0; k--) {
                    float s = -1.0f + i / 3.0f, t = -1.0f + (j + k) / 3.0f;
                    float p[3];
                    int m;
                    for (m = 0; m < 3; m++)
                        p[m] = n[f][m] + s * u[m] + t * v[m];
                    glVertex3f(p[0] * sx, p[1] * sy, p[2] * sz);
                }
            }
            glEnd();
        }
    }
}

int main(int argc, char **argv)
{
    GLUquadric *q;
    scene_begin(argc, argv, 256, 256);
    light_frustum(0.5f, 1.0f, 1.0f, 40.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHT2);
    light_all_black();
    light_model_ambient(0.08f, 0.08f, 0.11f, 1.0f);
    gluLookAt(0.0, 4.0, 9.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.0);

    /* the sun: low, warm, from the left */
    light_fv(GL_LIGHT0, GL_AMBIENT, 0.05f, 0.04f, 0.03f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.45f, 0.38f, 0.25f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.5f, 0.45f, 0.3f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -1.0f, 0.8f, 0.3f, 0.0f);
    /* the lamp: a bulb right of the centre, attenuated */
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.9f, 0.85f, 0.6f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPECULAR, 1.0f, 1.0f, 0.8f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, 2.2f, 1.6f, 1.0f, 1.0f);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.3f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.15f);
    /* the spotlight: cold, from above the back, onto the floor in front */
    light_fv(GL_LIGHT2, GL_DIFFUSE, 0.35f, 0.5f, 0.8f, 1.0f);
    light_fv(GL_LIGHT2, GL_SPECULAR, 0.8f, 0.9f, 1.0f, 1.0f);
    light_fv(GL_LIGHT2, GL_POSITION, -1.0f, 5.0f, -2.0f, 1.0f);
    light_fv(GL_LIGHT2, GL_SPOT_DIRECTION, 0.3f, -1.0f, 0.7f, 0.0f);
    glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 14.0f);
    glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 10.0f);

    /* floor */
    light_mat(GL_FRONT, GL_AMBIENT, 0.6f, 0.6f, 0.6f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.6f, 0.6f, 0.55f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.2f, 0.2f, 0.2f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 8.0f);
    light_floor(-5.0f, -5.0f, 5.0f, 5.0f, 0.0f, 80, 80);

    /* a shiny sphere */
    glPushMatrix();
    glTranslatef(-1.6f, 1.0f, 0.2f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.7f, 0.2f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.7f, 0.2f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 60.0f);
    light_sphere(1.0f, 48, 24);
    glPopMatrix();

    /* a matte box, turned */
    glPushMatrix();
    glTranslatef(1.0f, 0.7f, -1.2f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.3f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.3f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.1f, 0.1f, 0.1f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 5.0f);
    box(0.7f, 0.7f, 0.7f);
    glPopMatrix();

    /* a GLU cylinder standing in the spot */
    q = gluNewQuadric();
    gluQuadricNormals(q, GLU_SMOOTH);
    glPushMatrix();
    glTranslatef(0.4f, 0.0f, 1.6f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.8f, 0.7f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.7f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    gluCylinder(q, 0.4, 0.4, 1.4, 32, 6);
    glTranslatef(0.0f, 0.0f, 1.4f);
    gluDisk(q, 0.0, 0.4, 32, 2);
    glPopMatrix();
    gluDeleteQuadric(q);
    return scene_end();
}
