/* Modelview stack: nested glPushMatrix/glPopMatrix with glTranslatef,
 * glRotatef and glScalef (a small "orbit" of triangles). */
#include "scene.h"

static void tri(float r, float g, float b)
{
    glBegin(GL_TRIANGLES);
    glColor3f(r, g, b); glVertex2f(-1.0f, -0.8f);
    glColor3f(b, r, g); glVertex2f(1.0f, -0.6f);
    glColor3f(g, b, r); glVertex2f(0.1f, 1.0f);
    glEnd();
}

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 160, 160);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glTranslatef(80.0f, 80.0f, 0.0f);
    glPushMatrix();
    glScalef(14.0f, 14.0f, 1.0f);
    tri(1, 1, 1);
    glPopMatrix();
    for (i = 0; i < 7; i++) {
        glPushMatrix();
        glRotatef(i * 51.4f + 10.0f, 0.0f, 0.0f, 1.0f);
        glTranslatef(48.0f, 0.0f, 0.0f);
        glPushMatrix();
        glRotatef(-i * 33.0f, 0.0f, 0.0f, 1.0f);
        glScalef(10.0f + i, 7.0f, 1.0f);
        tri(1, i / 7.0f, 0.2f);
        glPopMatrix();
        glRotatef(i * 20.0f, 0.0f, 0.0f, 1.0f);   /* moon */
        glTranslatef(22.0f, 0.0f, 0.0f);
        glScalef(-4.0f, 4.0f, 1.0f);              /* mirrored */
        tri(0.1f, 0.6f, 1);
        glPopMatrix();
    }
    glPushMatrix();
    glTranslated(-70.0, -70.0, 0.0);              /* double variants */
    glRotated(30.0, 0.0, 0.0, 1.0);
    glScaled(6.0, 3.0, 1.0);
    tri(1, 0, 1);
    glPopMatrix();
    glTranslatef(60.0f, -66.0f, 0.0f);            /* after all pops */
    glScalef(9.0f, 9.0f, 1.0f);
    tri(0, 1, 0);
    return scene_end();
}
