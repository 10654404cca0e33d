/* light_glu_common.h - the lit GLU quadrics scene shared by light_glu_flat
 * and light_glu_smooth, which differ only in gluQuadricNormals. */
#ifndef LIGHT_GLU_COMMON_H
#define LIGHT_GLU_COMMON_H
#include "light_common.h"
#include <GL/glu.h>

static inline int light_glu_quadrics_scene(int argc, char **argv, GLenum normals)
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
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.75f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 2.0f, 4.0f, 3.0f, 0.0f);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.3f, 0.3f, 0.6f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, -3.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    q = gluNewQuadric();
    gluQuadricNormals(q, normals);

    glPushMatrix();
    glTranslatef(-1.3f, 0.2f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.2f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.2f, 0.2f, 1.0f);
    gluSphere(q, 1.0, 20, 12);
    glPopMatrix();

    /* a cone-ish cylinder standing up, open at both ends */
    glPushMatrix();
    glTranslatef(1.4f, -0.8f, -0.5f);
    glRotatef(-90.0f, 1, 0, 0);
    light_mat(GL_FRONT, GL_AMBIENT, 0.2f, 0.8f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.8f, 0.3f, 1.0f);
    gluCylinder(q, 0.7, 0.4, 1.8, 20, 4);
    glPopMatrix();

    /* a disk with a hole lying on the "floor" (facing up) */
    glPushMatrix();
    glTranslatef(0.0f, -1.2f, 1.0f);
    glRotatef(-90.0f, 1, 0, 0);
    light_mat(GL_FRONT, GL_AMBIENT, 0.2f, 0.4f, 0.95f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.4f, 0.95f, 1.0f);
    gluDisk(q, 0.3, 1.3, 28, 3);
    glPopMatrix();

    /* a partial disk facing the eye */
    glPushMatrix();
    glTranslatef(0.3f, 1.3f, 1.0f);
    glRotatef(-20.0f, 1, 0, 0);
    light_mat(GL_FRONT, GL_AMBIENT, 0.95f, 0.9f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.95f, 0.9f, 0.2f, 1.0f);
    gluPartialDisk(q, 0.2, 0.9, 20, 2, 30.0, 200.0);
    glPopMatrix();

    gluDeleteQuadric(q);
    return scene_end();
}

#endif
