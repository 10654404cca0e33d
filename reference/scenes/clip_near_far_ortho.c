/* Near and far clipping with glOrtho: smooth, depth-tested triangles whose
 * vertices lie in front of the near plane and behind the far plane. */
#include "scene.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 128, 0, 128, 0.5, 2.0);   /* visible eye z: -0.5 .. -2 */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(4.0f, 4.0f, 1.0f);      /* in front of near */
    glColor3f(0, 1, 0); glVertex3f(124.0f, 10.0f, -1.0f);
    glColor3f(0, 0, 1); glVertex3f(30.0f, 60.0f, -1.2f);
    glColor3f(1, 1, 0); glVertex3f(4.0f, 70.0f, -1.0f);
    glColor3f(0, 1, 1); glVertex3f(124.0f, 66.0f, -3.5f);  /* behind far */
    glColor3f(1, 0, 1); glVertex3f(60.0f, 124.0f, -1.5f);
    glColor3f(1, 1, 1); glVertex3f(70.0f, 30.0f, 0.2f);    /* crosses both */
    glColor3f(1, 0.5f, 0); glVertex3f(124.0f, 124.0f, -2.8f);
    glColor3f(0, 0.5f, 1); glVertex3f(90.0f, 124.0f, -1.0f);
    glEnd();
    return scene_end();
}
