/* Different polygon modes per face, culling off: front faces filled, back
 * faces as lines (left: an open, lit cylinder whose inside shows), then front
 * GL_POINT, back GL_FILL, and GL_POINT for both with culling of the back
 * (right), in two-sided lighting. */
#include <math.h>

#include "scene.h"

static void open_cylinder(float x, float y, int sides)
{
    int i;
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= sides; i++) {
        float a = (float)i / (float)sides * 6.28318530718f;
        glNormal3f(cosf(a), 0, sinf(a));
        glVertex3f(x + 0.7f * cosf(a), y - 0.8f, 0.7f * sinf(a));
        glVertex3f(x + 0.7f * cosf(a), y + 0.8f, 0.7f * sinf(a));
    }
    glEnd();
}

int main(int argc, char **argv)
{
    static const float light[4] = {0.3f, 0.5f, 1.0f, 0};
    static const float back[4] = {0.3f, 0.9f, 0.4f, 1};
    scene_begin(argc, argv, 160, 120);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.33, 1.33, -1, 1, 2, 12);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -4.5f);
    glRotatef(35, 1, 0, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back);
    glEnable(GL_DEPTH_TEST);

    glPolygonMode(GL_FRONT, GL_FILL);
    glPolygonMode(GL_BACK, GL_LINE);
    open_cylinder(-1.6f, 0, 16);

    glPolygonMode(GL_FRONT, GL_POINT);
    glPolygonMode(GL_BACK, GL_FILL);
    glPointSize(3);
    open_cylinder(0.1f, 0.3f, 12);

    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glEnable(GL_CULL_FACE);
    glPointSize(2);
    open_cylinder(1.7f, -0.2f, 20);
    return scene_end();
}
