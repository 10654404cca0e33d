/* Lists that hold state as well as geometry: a light placed under a rotation
 * inside a list, materials, glShadeModel, matrices pushed and popped, and
 * glColorMaterial with colours between glBegin/glEnd, around a lit sphere
 * mesh (triangle strips with a normal per vertex) called from other lists. */
#include <math.h>

#include "scene.h"

enum { LIGHTS = 1, SHINY, MATTE, SPHERE, FLAT_OBJECT, SMOOTH_OBJECT, PAINTED };

static void sphere(int slices, int stacks, int painted)
{
    int i, j;
    for (i = 0; i < stacks; i++) {
        const float t0 = (float)M_PI * i / stacks - (float)M_PI / 2;
        const float t1 = (float)M_PI * (i + 1) / stacks - (float)M_PI / 2;
        glBegin(GL_TRIANGLE_STRIP);
        for (j = 0; j <= slices; j++) {
            const float p = 2 * (float)M_PI * j / slices;
            if (painted) glColor3f(0.5f + 0.5f * cosf(p), 0.3f, 0.5f + 0.4f * sinf(t0));
            glNormal3f(cosf(t1) * cosf(p), sinf(t1), cosf(t1) * sinf(p));
            glVertex3f(cosf(t1) * cosf(p), sinf(t1), cosf(t1) * sinf(p));
            glNormal3f(cosf(t0) * cosf(p), sinf(t0), cosf(t0) * sinf(p));
            glVertex3f(cosf(t0) * cosf(p), sinf(t0), cosf(t0) * sinf(p));
        }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    static const GLfloat white[4] = {1, 1, 1, 1}, warm[4] = {1, 0.8f, 0.6f, 1};
    static const GLfloat pos0[4] = {0, 0, 10, 0}, pos1[4] = {-4, 3, 2, 1};
    static const GLfloat blue[4] = {0.2f, 0.3f, 0.9f, 1}, grey[4] = {0.5f, 0.5f, 0.5f, 1};
    static const GLfloat clay[4] = {0.7f, 0.4f, 0.2f, 1}, none[4] = {0, 0, 0, 1};
    scene_begin(argc, argv, 200, 160);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.25, 1.25, -1, 1, 3, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -8);
    glEnable(GL_DEPTH_TEST);

    glNewList(LIGHTS, GL_COMPILE);
    glPushMatrix();
    glRotatef(35, 0, 1, 0);
    glRotatef(-20, 1, 0, 0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glPopMatrix();
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.05f);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHTING);
    glEndList();

    glNewList(SHINY, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 40);
    glEndList();
    glNewList(MATTE, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, clay);
    glMaterialfv(GL_FRONT, GL_SPECULAR, none);
    glEndList();

    glNewList(SPHERE, GL_COMPILE);
    sphere(24, 12, 0);
    glEndList();

    glNewList(FLAT_OBJECT, GL_COMPILE);
    glPushMatrix();
    glTranslatef(-1.6f, 0.9f, 0);
    glScalef(0.9f, 0.9f, 0.9f);
    glShadeModel(GL_FLAT);
    glCallList(MATTE);
    glCallList(SPHERE);
    glShadeModel(GL_SMOOTH);
    glPopMatrix();
    glEndList();

    glNewList(SMOOTH_OBJECT, GL_COMPILE);
    glPushMatrix();
    glTranslatef(1.5f, 0.8f, -1);
    glRotatef(30, 1, 1, 0);
    glCallList(SHINY);
    glCallList(SPHERE);
    glPopMatrix();
    glEndList();

    glNewList(PAINTED, GL_COMPILE);
    glPushMatrix();
    glTranslatef(0, -1.3f, 0.5f);
    glScalef(1.4f, 0.7f, 0.9f);
    glEnable(GL_NORMALIZE);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glMaterialfv(GL_FRONT, GL_SPECULAR, grey);
    sphere(20, 10, 1);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_NORMALIZE);
    glPopMatrix();
    glEndList();

    scene_clear();
    glCallList(LIGHTS);
    glCallList(FLAT_OBJECT);
    glCallList(SMOOTH_OBJECT);
    glCallList(PAINTED);
    glPushMatrix();  /* the smooth object again, smaller, after the painted one */
    glTranslatef(-0.3f, 0.2f, 1.5f);
    glScalef(0.4f, 0.4f, 0.4f);
    glCallList(SMOOTH_OBJECT);
    glPopMatrix();
    return scene_end();
}
