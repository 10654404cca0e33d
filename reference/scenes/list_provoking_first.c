/* 3-vertex strips and fans in lists under GL_FIRST_VERTEX_CONVENTION, flat:
 * Mesa's save module turns a 3-vertex strip or fan into GL_TRIANGLES, except
 * the first primitive of a vertex node (merge_prims starts at the second), so
 * a fan alone in a list keeps the fan's provoking vertex (its second) while
 * a fan after another primitive takes the first. */
#include "scene.h"
static void fan(float x, float y, GLenum mode)
{
    glBegin(mode);
    glColor3f(1, 0, 0); glVertex2f(x, y);
    glColor3f(0, 1, 0); glVertex2f(x + 20, y);
    glColor3f(0, 0, 1); glVertex2f(x + 10, y + 20);
    glEnd();
}
int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 64);
    scene_ortho_pixels();
    glShadeModel(GL_FLAT);
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    glNewList(1, GL_COMPILE); fan(4, 4, GL_TRIANGLE_FAN); glEndList();
    glNewList(2, GL_COMPILE); fan(34, 4, GL_TRIANGLE_STRIP); glEndList();
    glNewList(3, GL_COMPILE); fan(64, 4, GL_TRIANGLES); fan(94, 4, GL_TRIANGLE_FAN); glEndList();
    glNewList(4, GL_COMPILE); fan(4, 34, GL_TRIANGLE_FAN); fan(34, 34, GL_TRIANGLE_FAN); glEndList();
    glCallList(1); glCallList(2); glCallList(3); glCallList(4);
    return scene_end();
}
