/* Colour rounding in list replays: 0.5-tie colours in perspective, drawn
 * from lists whose colour is a command before glBegin (outside the vertex
 * node: Mesa's fragment shader reads it as a constant), set once inside
 * glBegin/glEnd (per-vertex data of the node, interpolated), or inherited
 * from the caller, and in GL_COMPILE_AND_EXECUTE. */
#include "scene.h"

static const float kTies[4] = {0.3f, 0.9f, 0.5f, 0.1f};

static void strip(int i, int where)  /* where: 0 colour before glBegin, 1 inside, 2 none */
{
    const float a = -1.0f + i * 0.5f + 0.03f, b = a + 0.44f, m = 0.5f * (a + b), t = kTies[i];
    if (where == 0) glColor3f(t, 1 - t, t);
    glBegin(GL_QUAD_STRIP);
    if (where == 1) glColor3f(t, 1 - t, t);
    glVertex3f(a * 1.5f, -0.3f, -1.5f); glVertex3f(a * 1.5f, 0.3f, -1.5f);
    glVertex3f(m * 3.0f, -0.6f, -3.0f); glVertex3f(m * 3.0f, 0.6f, -3.0f);
    glVertex3f(b * 6.0f, -1.2f, -6.0f); glVertex3f(b * 6.0f, 1.2f, -6.0f);
    glEnd();
}

static void band(int row)
{
    glViewport(0, row * 24, 128, 24);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.25, 0.25, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 128, 120);
    glShadeModel(GL_SMOOTH);
    for (i = 0; i < 3; i++) {
        int k;
        glNewList(1 + i, GL_COMPILE);
        for (k = 0; k < 4; k++) strip(k, i);
        glEndList();
    }
    band(0);
    glCallList(1);
    band(1);
    glCallList(2);
    band(2);
    glColor3f(0.5f, 0.5f, 128.5f / 255);
    glCallList(3);
    band(3);
    glNewList(4, GL_COMPILE_AND_EXECUTE);
    for (i = 0; i < 4; i++) strip(i, i % 2);
    glEndList();
    band(4);
    glCallList(4);
    return scene_end();
}
