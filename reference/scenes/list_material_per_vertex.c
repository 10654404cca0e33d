/* glMaterial between glBegin and glEnd in lists, lit: a quad whose vertices
 * change the diffuse material, drawn in immediate mode, from a
 * GL_COMPILE_AND_EXECUTE list, from a GL_COMPILE list, alone and after another
 * glBegin/glEnd pair of the same node (the glMaterial ends the node there). */
#include "scene.h"
static const GLfloat red[4] = {0.9f, 0.2f, 0.1f, 1}, teal[4] = {0.1f, 0.7f, 0.6f, 1};
static void pvquad(float x, float y)
{
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glVertex2f(x, y);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, teal);
    glVertex2f(x + 16, y);
    glVertex2f(x + 16, y + 16);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glVertex2f(x, y + 16);
    glEnd();
}
static void quad(float x, float y)
{
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glVertex2f(x, y); glVertex2f(x + 16, y); glVertex2f(x + 16, y + 16); glVertex2f(x, y + 16);
    glEnd();
}
int main(int argc, char **argv)
{
    static const GLfloat dir[4] = {0.3f, 0.4f, 1, 0}, grey[4] = {0.5f, 0.5f, 0.5f, 1};
    scene_begin(argc, argv, 120, 100);
    scene_ortho_pixels();
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glShadeModel(GL_SMOOTH);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    pvquad(4, 4);                                   /* cell 0,0 immediate */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    glNewList(1, GL_COMPILE_AND_EXECUTE); pvquad(28, 4); glEndList();   /* cell 1,0 */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    glNewList(2, GL_COMPILE); pvquad(52, 4); glEndList();
    glCallList(2);                                  /* cell 2,0 */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    glNewList(3, GL_COMPILE_AND_EXECUTE); quad(4, 28); pvquad(28, 28); glEndList();  /* cells 0,1 1,1 */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    glNewList(4, GL_COMPILE); quad(52, 28); pvquad(76, 28); glEndList();
    glCallList(4);                                  /* cells 2,1 3,1 */
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    quad(4, 52); pvquad(28, 52);                    /* cells 0,2 1,2 immediate */
    return scene_end();
}
