/* Random triangle strips and fans in perspective (glFrustum + depth), with
 * random flat colours (last-vertex convention). */
#include "scene.h"

int main(int argc, char **argv)
{
    int i, v;
    scene_begin(argc, argv, 200, 150);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -0.75, 0.75, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    scene_srand(4242u);
    for (i = 0; i < 60; i++) {
        float cx = scene_randf(-6, 6), cy = scene_randf(-4, 4), cz = scene_randf(-19, -2);
        glBegin((i & 1) ? GL_TRIANGLE_STRIP : GL_TRIANGLE_FAN);
        for (v = 0; v < 8; v++) {
            glColor3ub((GLubyte)(scene_rand() & 255), (GLubyte)(scene_rand() & 255),
                       (GLubyte)(scene_rand() & 255));
            glVertex3f(cx + scene_randf(-2, 2), cy + scene_randf(-2, 2), cz + scene_randf(-2, 2));
        }
        glEnd();
    }
    return scene_end();
}
