/* Lit GLU quadrics with gluQuadricOrientation GLU_INSIDE and back-face culling: inner surfaces of a sphere, an open cylinder and disks. */
#include "light_common.h"
#include <GL/glu.h>

int main(int argc, char **argv)
{
    GLUquadric *q;
    scene_begin(argc, argv, 192, 144);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, 192.0 / 144.0, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(2.0, 3.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 1.0f, 1.0f, 2.0f, 0.0f);
    /* a lamp inside the sphere */
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.9f, 0.6f, 0.2f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, -1.3f, 0.2f, 0.0f, 1.0f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
    q = gluNewQuadric();
    gluQuadricNormals(q, GLU_SMOOTH);
    gluQuadricOrientation(q, GLU_INSIDE);

    /* sphere: the near half is culled, the inside of the far half shows */
    glPushMatrix();
    glTranslatef(-1.3f, 0.2f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.3f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.3f, 0.3f, 1.0f);
    gluSphere(q, 1.0, 24, 16);
    glPopMatrix();

    /* open cylinder, axis tilted towards the eye */
    glPushMatrix();
    glTranslatef(1.4f, 0.0f, -0.5f);
    glRotatef(-60.0f, 1, 0, 0);
    light_mat(GL_FRONT, GL_AMBIENT, 0.2f, 0.8f, 0.4f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.8f, 0.4f, 1.0f);
    gluCylinder(q, 0.7, 0.7, 1.6, 24, 3);
    glPopMatrix();

    /* GLU_INSIDE disks face -z (normal and winding): rotated so that side
     * faces the eye */
    glPushMatrix();
    glTranslatef(0.0f, -1.2f, 1.0f);
    glRotatef(90.0f, 1, 0, 0);
    light_mat(GL_FRONT, GL_AMBIENT, 0.3f, 0.4f, 0.95f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.3f, 0.4f, 0.95f, 1.0f);
    gluDisk(q, 0.3, 1.3, 28, 3);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.3f, 1.3f, 1.0f);
    glRotatef(180.0f, 0, 1, 0);
    light_mat(GL_FRONT, GL_AMBIENT, 0.95f, 0.9f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.95f, 0.9f, 0.2f, 1.0f);
    gluPartialDisk(q, 0.2, 0.9, 20, 2, 0.0, 200.0);
    glPopMatrix();

    gluDeleteQuadric(q);
    return scene_end();
}
