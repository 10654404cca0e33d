/* Lit GLU spheres sliced by two user clip planes set under different modelview matrices (one before, one after a rotation and translation), flat on the left, smooth on the right; two-sided lighting shows the inside. */
#include "light_common.h"
#include <GL/glu.h>

static void sliced_sphere(GLUquadric *q, float x, GLenum shade)
{
    /* Plane 0 in the sphere's own frame: keep y <= 0.25, opening the top (set after the
       translation). Plane 1 in a rotated frame: a tilted cut. */
    const GLdouble keep_below[4] = {0.0, -1.0, 0.0, 0.25};
    const GLdouble tilted[4] = {1.0, 0.0, 0.0, 0.3};
    glShadeModel(shade);
    glPushMatrix();
    glTranslatef(x, 0.0f, 0.0f);
    glClipPlane(GL_CLIP_PLANE0, keep_below);
    glPushMatrix();
    glRotatef(40.0f, 0.3f, 0.2f, 1.0f);
    glClipPlane(GL_CLIP_PLANE1, tilted);
    glPopMatrix();
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    gluSphere(q, 1.0, 24, 16);
    glPopMatrix();
}

int main(int argc, char **argv)
{
    GLUquadric *q;
    scene_begin(argc, argv, 192, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, 192.0 / 128.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.5, 1.5, 5.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    light_all_black();
    light_model_ambient(0.2f, 0.2f, 0.2f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.85f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 2.0f, 5.0f, 4.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.8f, 0.3f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.3f, 0.2f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
    light_mat(GL_BACK, GL_AMBIENT, 0.2f, 0.5f, 0.9f, 1.0f);
    light_mat(GL_BACK, GL_DIFFUSE, 0.2f, 0.5f, 0.9f, 1.0f);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    q = gluNewQuadric();
    gluQuadricNormals(q, GLU_SMOOTH);
    sliced_sphere(q, -1.2f, GL_FLAT);
    sliced_sphere(q, 1.2f, GL_SMOOTH);
    gluDeleteQuadric(q);
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE1);
    scene_readpixels_check();
    return scene_end();
}
