/* Edge flags in GL_LINE mode: quads and polygons whose inner edges are hidden
 * by glEdgeFlag between glBegin and glEnd, by an edge flag array
 * (glDrawArrays and glDrawElements), and from a display list; GL_POINT mode
 * drops the vertices whose edge is hidden; a triangle strip ignores them. */
#include "scene.h"

static const GLfloat grid[] = {10, 10, 40, 10, 40, 40, 10, 40, 40, 10, 70, 10, 70, 40, 40, 40};
static const GLboolean gridFlags[] = {1, 1, 0, 1, 1, 1, 1, 0};

static void hexagon(float cx, float cy, float r, int hideEvery)
{
    int i;
    glBegin(GL_POLYGON);
    for (i = 0; i < 6; i++) {
        static const float c[6][2] = {{1, 0}, {0.5f, 0.866f}, {-0.5f, 0.866f},
                                      {-1, 0}, {-0.5f, -0.866f}, {0.5f, -0.866f}};
        glEdgeFlag(hideEvery && i % hideEvery == 0 ? GL_FALSE : GL_TRUE);
        glColor3f(0.4f + 0.1f * (float)i, 1.0f - 0.12f * (float)i, 0.5f);
        glVertex2f(cx + r * c[i][0], cy + r * c[i][1]);
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
}

int main(int argc, char **argv)
{
    GLuint list;
    static const GLubyte indices[] = {4, 5, 6, 7, 0, 1, 2, 3};
    scene_begin(argc, argv, 160, 128);
    scene_ortho_pixels();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);

    /* two quads sharing an edge, hidden from one side by glEdgeFlag */
    glBegin(GL_QUADS);
    glColor3f(1, 0.3f, 0.2f);
    glVertex2f(5, 70); glVertex2f(35, 72);
    glEdgeFlag(GL_FALSE);
    glVertex2f(37, 100);
    glEdgeFlag(GL_TRUE);
    glVertex2f(6, 98);
    glColor3f(0.3f, 0.6f, 1);
    glVertex2f(35, 72);
    glEdgeFlag(GL_FALSE);
    glVertex2f(66, 71);
    glEdgeFlag(GL_TRUE);
    glVertex2f(64, 99); glVertex2f(37, 100);
    glEnd();

    /* polygons: all edges, every second hidden, every third hidden */
    hexagon(90, 90, 16, 0);
    hexagon(130, 90, 16, 2);
    hexagon(110, 50, 14, 3);

    /* the edge flag array */
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, grid);
    glEdgeFlagPointer(0, gridFlags);
    glColor3f(0.9f, 0.9f, 0.3f);
    glDrawArrays(GL_QUADS, 0, 8);
    glTranslatef(0, 20, 0);
    glColor3f(0.9f, 0.5f, 0.9f);
    glPushMatrix();
    glTranslatef(80, -28, 0);
    glDrawElements(GL_QUADS, 8, GL_UNSIGNED_BYTE, indices);
    glPopMatrix();
    glTranslatef(0, -20, 0);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);

    /* a display list with edge flags between glBegin and glEnd */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.5f, 1, 1);
    glVertex2f(75, 20);
    glEdgeFlag(GL_FALSE);
    glVertex2f(100, 22);
    glEdgeFlag(GL_TRUE);
    glVertex2f(90, 44);
    glEnd();
    glEndList();
    glCallList(list);
    glTranslatef(30, 0, 0);
    glCallList(list);
    glTranslatef(-30, 0, 0);

    /* GL_POINT: the vertex of each hidden edge is not drawn */
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3);
    hexagon(30, 115, 10, 2);

    /* a strip: edge flags do not apply (GL 2.1 §3.6.4), all flags true here */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_TRIANGLE_STRIP);
    glColor3f(1, 1, 1);
    glVertex2f(60, 105); glVertex2f(70, 125); glVertex2f(80, 105); glVertex2f(90, 125);
    glEnd();
    return scene_end();
}
