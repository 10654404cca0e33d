/* Lit lines of a mesh (a wire torus: rings as GL_LINE_LOOP, meridians as
 * GL_LINE_STRIP, spokes as GL_LINES), flat and smooth, with the depth test. */
#include <math.h>

#include "scene.h"

static void torus_vertex(float R, float r, int i, int j, int ni, int nj)
{
    float u = 6.2831853f * (float)i / (float)ni, v = 6.2831853f * (float)j / (float)nj;
    float cu = cosf(u), su = sinf(u), cv = cosf(v), sv = sinf(v);
    glNormal3f(cu * cv, su * cv, sv);
    glVertex3f((R + r * cv) * cu, (R + r * cv) * su, r * sv);
}

static void torus(int flat)
{
    int i, j;
    const int ni = 24, nj = 12;
    glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
    for (i = 0; i < ni; i++) {
        glBegin(GL_LINE_LOOP);
        for (j = 0; j < nj; j++) torus_vertex(0.6f, 0.25f, i, j, ni, nj);
        glEnd();
    }
    for (j = 0; j < nj; j++) {
        glBegin(GL_LINE_STRIP);
        for (i = 0; i <= ni; i++) torus_vertex(0.6f, 0.25f, i, j, ni, nj);
        glEnd();
    }
    glBegin(GL_LINES);
    for (i = 0; i < ni; i += 2) {
        torus_vertex(0.6f, 0.25f, i, 0, ni, nj);
        torus_vertex(0.6f, 0.25f, i + 1, nj / 2, ni, nj);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLfloat pos[] = {-0.5f, 0.7f, 1.0f, 0.0f};
    static const GLfloat diffuse[] = {0.9f, 0.6f, 0.3f, 1.0f};
    static const GLfloat specular[] = {0.8f, 0.8f, 0.8f, 1.0f};
    scene_begin(argc, argv, 200, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.5, 0.5, 1.5, 6.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
    glLoadIdentity();
    glTranslatef(-0.75f, 0.0f, -3.0f);
    glRotatef(60.0f, 1.0f, 0.2f, 0.0f);
    torus(0);
    glLoadIdentity();
    glTranslatef(0.75f, 0.0f, -3.2f);
    glRotatef(-50.0f, 1.0f, -0.3f, 0.0f);
    torus(1);
    return scene_end();
}
