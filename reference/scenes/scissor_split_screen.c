/* Four scissored viewports, each cleared to its own colour and depth with glClear under the scissor, then drawn lit (a GLU sphere and a torus-like ring that spill past the viewport edges) with a perspective of its own; the last quarter's scissor box is smaller than its viewport. */
#include "light_common.h"
#include <GL/glu.h>

static void quarter(GLUquadric *q, int x, int y, int w, int h, const float clear[3], float angle, int inner)
{
    glViewport(x, y, w, h);
    if (inner)
        glScissor(x + 6, y + 4, w - 14, h - 10);
    else
        glScissor(x, y, w, h);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(clear[0], clear[1], clear[2], 1.0f);
    glClearDepth(inner ? 0.9 : 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 1.0, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(angle, 0.2f, 1.0f, 0.1f);
    light_fv(GL_LIGHT0, GL_POSITION, 1.0f, 3.0f, 2.0f, 0.0f);
    glPushMatrix();
    glTranslatef(-0.6f, 0.0f, 0.0f);
    gluSphere(q, 1.3, 20, 14);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.2f, -0.3f, 0.5f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    gluCylinder(q, 1.0, 1.0, 0.6, 24, 2);
    glPopMatrix();
}

int main(int argc, char **argv)
{
    const float colours[4][3] = {{0.1f, 0.2f, 0.3f}, {0.4f, 0.1f, 0.1f}, {0.1f, 0.35f, 0.1f}, {0.3f, 0.3f, 0.05f}};
    GLUquadric *q;
    scene_begin(argc, argv, 200, 150);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.2f, 0.2f, 0.2f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.85f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.8f, 0.8f, 0.8f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.7f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.7f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.4f, 0.4f, 0.4f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    q = gluNewQuadric();
    gluQuadricNormals(q, GLU_SMOOTH);
    quarter(q, 0, 0, 100, 75, colours[0], 0.0f, 0);
    quarter(q, 100, 0, 100, 75, colours[1], 40.0f, 0);
    glShadeModel(GL_FLAT);
    quarter(q, 0, 75, 100, 75, colours[2], 80.0f, 0);
    glShadeModel(GL_SMOOTH);
    quarter(q, 100, 75, 100, 75, colours[3], 120.0f, 1);
    gluDeleteQuadric(q);
    scene_readpixels_check();
    return scene_end();
}
