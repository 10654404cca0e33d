/* Lines crossing every frustum plane, smooth and flat colours across the cut,
 * lines far outside and lines whose ends are both outside but which cross the
 * view; orthographic (x, y, near, far) and perspective (near, w < 0). */
#include "scene.h"

static void line(float r0, float g0, float b0, float x0, float y0, float z0, float r1, float g1, float b1,
                 float x1, float y1, float z1)
{
    glColor3f(r0, g0, b0);
    glVertex3f(x0, y0, z0);
    glColor3f(r1, g1, b1);
    glVertex3f(x1, y1, z1);
}

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 128, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        float f = (float)i;
        line(1, 0, 0, -40.0f - 10 * f, 3.3f + 4 * f, 0, 0, 1, 0, 50.0f, 7.1f + 3 * f, 0);       /* left */
        line(0, 0, 1, 70.0f, 3.6f + 4 * f, 0, 1, 1, 0, 200.0f + 20 * f, 30.2f + 2 * f, 0);    /* right */
        line(1, 0, 1, 5.3f + 6 * f, 60.0f, 0, 0, 1, 1, 9.7f + 5 * f, -90.0f, 0);              /* bottom */
        line(0, 1, 1, 70.2f + 6 * f, 70.0f, 0, 1, 0.5f, 0, 60.9f + 7 * f, 300.0f, 0);         /* top */
        line(1, 1, 1, 10.0f, 40.4f + 2 * f, -3.0f, 0, 0, 1, 118.0f, 44.8f + 2 * f, 0.5f);      /* near */
        line(1, 0, 0, 10.0f, 80.6f + 2 * f, 0.5f, 0, 1, 0, 118.0f, 78.1f + 2 * f, 4.0f);       /* far */
    }
    line(1, 1, 0, -1e6f, 100.5f, 0, 0, 1, 1, 1e6f, 101.5f, 0);   /* both ends far outside */
    line(1, 1, 0, -300.0f, -300.0f, 0, 0, 0, 1, -200.0f, 500.0f, 0); /* wholly outside */
    line(1, 0, 1, -10.0f, 138.0f, 0, 0, 1, 0, 138.0f, -10.0f, 0); /* corner to corner */
    glEnd();
    glShadeModel(GL_FLAT);
    glBegin(GL_LINE_STRIP);
    glColor3f(1, 0, 0); glVertex2f(-20.0f, 120.0f);
    glColor3f(0, 1, 0); glVertex2f(60.0f, 124.0f);
    glColor3f(0, 0, 1); glVertex2f(150.0f, 118.0f);
    glColor3f(1, 1, 1); glVertex2f(100.0f, 140.0f);
    glEnd();
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    glBegin(GL_LINE_LOOP);
    glColor3f(1, 0.5f, 0); glVertex2f(-20.0f, 110.0f);
    glColor3f(0, 0.5f, 1); glVertex2f(150.0f, 112.0f);
    glColor3f(0.5f, 1, 0); glVertex2f(64.0f, 150.0f);
    glEnd();
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);

    /* perspective: lines through the near plane and behind the eye */
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_LINES);
    for (i = 0; i < 6; i++) {
        float f = (float)i;
        line(1, 0, 0, -0.8f + 0.3f * f, -0.9f, -2.0f, 0, 0, 1, -0.5f + 0.2f * f, -0.2f, 3.0f);
        line(0, 1, 0, 0.9f, -0.7f + 0.25f * f, -9.0f, 1, 1, 1, 0.2f, -0.6f + 0.2f * f, -12.0f);
    }
    glEnd();
    return scene_end();
}
