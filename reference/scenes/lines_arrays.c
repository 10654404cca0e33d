/* Every line mode through glDrawArrays and glDrawElements, flat (both
 * provoking-vertex conventions) and smooth, and a display list. */
#include "scene.h"

#define N 12
static GLfloat pos[N][2];
static GLfloat col[N][3];

static void fill(float y0)
{
    int i;
    for (i = 0; i < N; i++) {
        pos[i][0] = 6.0f + 9.5f * (float)i + (i & 1 ? 0.3f : 0.0f);
        pos[i][1] = y0 + ((i & 1) ? 9.25f : 0.5f) + 0.1f * (float)i;
        col[i][0] = (float)i / (N - 1);
        col[i][1] = 1.0f - (float)i / (N - 1);
        col[i][2] = (i % 3) / 2.0f;
    }
}

int main(int argc, char **argv)
{
    static const GLushort idx[] = {0, 2, 1, 3, 5, 4, 6, 8, 7, 9, 11, 10};
    static const GLenum modes[] = {GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP};
    int m, s;
    float y = 2.0f;
    GLuint list;
    scene_begin(argc, argv, 128, 224);
    scene_ortho_pixels();
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(3, GL_FLOAT, 0, col);
    for (s = 0; s < 3; s++) {
        glShadeModel(s == 0 ? GL_SMOOTH : GL_FLAT);
        glProvokingVertex(s == 2 ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION);
        for (m = 0; m < 3; m++) {
            fill(y);
            glDrawArrays(modes[m], 0, N);
            y += 11.0f;
        }
        for (m = 0; m < 3; m++) {
            fill(y);
            glDrawElements(modes[m], N, GL_UNSIGNED_SHORT, idx);
            y += 11.0f;
        }
    }
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glShadeModel(GL_SMOOTH);
    fill(y);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawArrays(GL_LINE_LOOP, 0, N);
    glBegin(GL_LINE_STRIP);
    glColor3f(1, 1, 1); glVertex2f(3.0f, 3.0f + y);
    glColor3f(0, 0, 1); glVertex2f(120.0f, 8.0f + y);
    glEnd();
    glEndList();
    glDisableClientState(GL_COLOR_ARRAY);
    glCallList(list);
    return scene_end();
}
