/* GL_POINTS from glDrawArrays, glDrawElements, glArrayElement and display
 * lists (including glPointSize compiled into the list and an array draw
 * compiled into a list): colours per vertex, flat and smooth, sizes 1 to 7,
 * some vertices outside the view, a long draw that Mesa cuts into segments. */
#include "scene.h"

#define N 600

static GLfloat pos[N][3];
static GLubyte col[N][4];
static GLushort idx[N];

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 192);
    scene_ortho_pixels();
    glEnable(GL_DEPTH_TEST);
    scene_srand(5);
    for (int i = 0; i < N; ++i) {
        pos[i][0] = scene_randf(-8.0f, 200.0f); /* some outside the view */
        pos[i][1] = scene_randf(0.0f, 192.0f);
        pos[i][2] = scene_randf(-0.9f, 0.9f);
        col[i][0] = (GLubyte)(scene_rand() & 255);
        col[i][1] = (GLubyte)(scene_rand() & 255);
        col[i][2] = (GLubyte)(scene_rand() & 255);
        col[i][3] = 255;
        idx[i] = (GLushort)((i * 7) % N);
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);

    glPointSize(1.0f);
    glDrawArrays(GL_POINTS, 0, 200);
    glPointSize(2.5f);
    glShadeModel(GL_FLAT);
    glDrawElements(GL_POINTS, 100, GL_UNSIGNED_SHORT, idx + 200);
    glShadeModel(GL_SMOOTH);
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (int i = 300; i < 340; ++i) glArrayElement(i);
    glEnd();

    GLuint list = glGenLists(2);
    glNewList(list, GL_COMPILE);
    glPointSize(3.0f);
    glDrawArrays(GL_POINTS, 340, 100);
    glPointSize(7.0f);
    glDrawElements(GL_POINTS, 30, GL_UNSIGNED_SHORT, idx + 440);
    glEndList();
    glNewList(list + 1, GL_COMPILE);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(20.5f, 20.5f, 0.95f);
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex3f(170.0f, 20.0f, 0.95f);
    glEnd();
    glEndList();

    glCallList(list);
    glTranslatef(3.0f, 2.0f, 0.0f);
    glCallList(list + 1);
    glDisableClientState(GL_COLOR_ARRAY);
    glColor3f(0.9f, 0.4f, 0.1f);
    glPointSize(1.5f);
    glDrawArrays(GL_POINTS, 470, N - 470);
    return scene_end();
}
