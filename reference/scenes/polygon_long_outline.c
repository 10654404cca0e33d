/* A 5000-vertex GL_POLYGON in GL_LINE mode and a 5000-vertex fan in GL_POINT
 * mode: Mesa draws them in segments, and the polygon's split edges stay
 * hidden (only its outline is drawn). */
#include <math.h>

#include "scene.h"

int main(int argc, char **argv)
{
    int i;
    const int n = 5000;
    scene_begin(argc, argv, 128, 128);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_POLYGON);
    for (i = 0; i < n; i++) {
        float a = 6.28318530718f * (float)i / (float)n;
        float r = (i & 1) ? 0.9f : 0.6f;
        glColor3f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a), 0.5f);
        glVertex2f(r * cosf(a), r * sinf(a));
    }
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(0, 0);
    for (i = 1; i < n; i++) {
        float a = 6.28318530718f * (float)i / (float)n;
        glColor3f(0.5f + 0.5f * cosf(a), 0.3f, 0.5f);
        glVertex2f(0.4f * cosf(a), 0.4f * sinf(a));
    }
    glEnd();
    return scene_end();
}
