/* glPointParameter distance attenuation: size / sqrt(a + b d + c d^2), d =
 * |z_eye|, in a perspective view; GL_POINT_SIZE_MIN and _MAX clamps; a
 * negative factor (RSQ of its absolute value); a fade threshold above the
 * sizes (no visible effect in Mesa); NaN, 0 and 1e30 coefficients; lit and
 * unlit, a rotated modelview. */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>

#include "light_common.h"

#ifndef GL_POINT_SIZE_MIN
#include <GL/glext.h>
#endif

static void row(float y, int n, float z0, float z1)
{
    glBegin(GL_POINTS);
    for (int i = 0; i < n; ++i) {
        float f = (float)i / (float)(n - 1);
        glColor3f(1.0f - f, 0.3f + 0.5f * f, f);
        glNormal3f(0.0f, 0.0f, 1.0f);
        glVertex3f(-3.0f + 6.0f * f, y, z0 + (z1 - z0) * f);
    }
    glEnd();
}

static void attenuation(float a, float b, float c)
{
    GLfloat v[3];
    v[0] = a;
    v[1] = b;
    v[2] = c;
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, v);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 224, 192);
    light_frustum(0.8f, 224.0f / 192.0f, 1.0f, 30.0f);
    glEnable(GL_DEPTH_TEST);
    glTranslatef(0.0f, 0.0f, -4.0f);

    glPointSize(12.0f);
    attenuation(0.0f, 0.0f, 0.08f); /* 12 / (0.283 d) */
    row(2.6f, 24, 1.0f, -14.0f);
    attenuation(0.2f, 0.3f, 0.0f);
    row(2.0f, 24, 2.0f, -10.0f);
    attenuation(1.0f, 0.0f, 0.01f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 40.0f); /* no visible effect */
    row(1.4f, 24, 2.5f, -12.0f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1.0f);

    /* Clamps: min 3, max 7.5; then a minimum above the maximum. */
    attenuation(0.0f, 0.15f, 0.02f);
    glPointParameterf(GL_POINT_SIZE_MIN, 3.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 7.5f);
    row(0.8f, 24, 3.0f, -14.0f);
    glPointParameterf(GL_POINT_SIZE_MIN, 6.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 4.0f);
    row(0.2f, 12, 3.0f, -14.0f);
    glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 255.0f);

    /* A negative factor, fractional sizes, a rotated and scaled modelview, lit. */
    glPushMatrix();
    glRotatef(35.0f, 0.0f, 1.0f, 0.0f);
    glScalef(1.0f, 1.0f, 1.5f);
    attenuation(-2.0f, 0.0f, 0.0f);
    glPointSize(7.0f);
    row(-0.4f, 20, 1.0f, -2.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
    attenuation(0.5f, 0.1f, 0.05f);
    glPointSize(5.5f);
    row(-1.0f, 20, 2.0f, -8.0f);
    glDisable(GL_LIGHTING);
    glPopMatrix();

    /* Bad coefficients: NaN gives the minimum, 0 and 1e-30 the maximum, 1e30 the minimum. */
    glPointParameterf(GL_POINT_SIZE_MAX, 9.0f);
    glPointSize(5.0f);
    attenuation(NAN, 0.0f, 0.0f);
    row(-1.6f, 6, 0.0f, -4.0f);
    attenuation(0.0f, 0.0f, 0.0f);
    row(-2.1f, 6, 0.0f, -4.0f);
    attenuation(1e30f, 0.0f, 0.0f);
    row(-2.5f, 6, 0.0f, -4.0f);
    attenuation(0.0f, 1e-30f, 0.0f);
    glPointSize(1e30f);
    row(-2.9f, 6, 0.0f, -4.0f);
    glPointSize(NAN);
    attenuation(0.0f, 0.5f, 0.0f);
    row(-3.2f, 6, 0.0f, -4.0f);
    return scene_end();
}
