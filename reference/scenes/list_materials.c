/* glMaterial in lists, lit: in GL_COMPILE_AND_EXECUTE Mesa runs a glMaterial
 * before it feeds back the vertices compiled before it (so they are lit with
 * the new material), and a glMaterial that repeats the list's last values is
 * not compiled; a glMaterial between glBegin and glEnd is a vertex attribute
 * that ends the vertex node before it. The list runs while compiled (top
 * rows) and again when called. */
#include "scene.h"

static void quad(float x, float y, float s)
{
    glBegin(GL_QUADS);
    glNormal3f(-0.5f, -0.4f, 1); glVertex2f(x, y);
    glNormal3f(0.6f, -0.3f, 1);  glVertex2f(x + s, y);
    glNormal3f(0.4f, 0.5f, 1);   glVertex2f(x + s, y + s);
    glNormal3f(-0.3f, 0.6f, 1);  glVertex2f(x, y + s);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLfloat red[4] = {0.9f, 0.2f, 0.1f, 1}, teal[4] = {0.1f, 0.7f, 0.6f, 1};
    static const GLfloat spec[4] = {0.8f, 0.8f, 0.8f, 1}, dir[4] = {0.3f, 0.4f, 1, 0};
    scene_begin(argc, argv, 160, 100);
    scene_ortho_pixels();
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_SMOOTH);

    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glTranslatef(0, 52, 0);
    quad(4, 4, 16);                               /* fed back after the glMaterial ran */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    quad(28, 4, 16);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);      /* repeats: not compiled */
    quad(52, 4, 16);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 20);
    quad(76, 4, 16);
    glBegin(GL_QUADS);                            /* per-vertex material */
    glNormal3f(0, 0, 1);
    glVertex2f(100, 4);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, teal);
    glVertex2f(116, 4);
    glVertex2f(116, 20);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glVertex2f(100, 20);
    glEnd();
    glMaterialfv(GL_FRONT, GL_DIFFUSE, teal);
    quad(124, 4, 16);
    glTranslatef(0, 24, 0);
    quad(4, 4, 16);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
    quad(28, 4, 16);
    glEndList();

    glLoadIdentity();
    glTranslatef(0, -50, 0);  /* the replay below what the compile drew */
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glCallList(1);
    return scene_end();
}
