/* Fog from explicit fog coordinates (GL_FOG_COORD_SRC = GL_FOG_COORD, GL 2.1
 * §3.10): per vertex in glBegin/glEnd, from a fog coordinate array (client
 * memory and a buffer object), through a display list, negative coordinates
 * (their absolute value is used) and the current coordinate for a whole quad. */
#include "scene.h"

static void quad(float x, float y, float w, float h, const float fog[4]) {
  glBegin(GL_QUADS);
  glFogCoordf(fog[0]); glVertex2f(x, y);
  glFogCoordf(fog[1]); glVertex2f(x + w, y);
  glFogCoordf(fog[2]); glVertex2f(x + w, y + h);
  glFogCoordf(fog[3]); glVertex2f(x, y + h);
  glEnd();
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 160, 160);
    scene_ortho_pixels();
    glClearColor(0.1f, 0.1f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    const GLfloat fogColor[4] = {0.9f, 0.8f, 0.6f, 1};
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fogColor);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);

    /* Linear, per vertex, with a smooth colour underneath. */
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 1.0f);
    glFogf(GL_FOG_END, 9.0f);
    glShadeModel(GL_SMOOTH);
    {
        const float f[4] = {0, 10, 4, -6};
        glBegin(GL_TRIANGLES);
        glColor3f(0.2f, 0.3f, 0.9f); glFogCoordf(f[0]); glVertex2f(5, 5);
        glColor3f(0.9f, 0.1f, 0.1f); glFogCoordf(f[1]); glVertex2f(75, 10);
        glColor3f(0.1f, 0.8f, 0.2f); glFogCoordf(f[2]); glVertex2f(30, 70);
        glEnd();
        glColor3f(0.3f, 0.1f, 0.5f);
        quad(85, 5, 70, 65, f);
    }

    /* GL_EXP from a fog coordinate array, client memory, then a buffer object. */
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.35f);
    {
        static const GLfloat pos[8] = {5, 80, 75, 80, 75, 115, 5, 115};
        static const GLfloat fog[4] = {0.5f, 6.0f, 2.0f, -3.0f};
        static const GLdouble fogd[4] = {3.0, 0.25, 7.0, 1.5};
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_FOG_COORD_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, pos);
        glFogCoordPointer(GL_FLOAT, 0, fog);
        glColor3f(0.8f, 0.8f, 0.1f);
        glDrawArrays(GL_QUADS, 0, 4);

        GLuint buf;
        glGenBuffers(1, &buf);
        glBindBuffer(GL_ARRAY_BUFFER, buf);
        glBufferData(GL_ARRAY_BUFFER, sizeof fogd, fogd, GL_STATIC_DRAW);
        glFogCoordPointer(GL_DOUBLE, 0, (const void *)0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glPushMatrix();
        glTranslatef(80, 0, 0);
        glColor3f(0.1f, 0.6f, 0.7f);
        static const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
        glPopMatrix();
        glDisableClientState(GL_FOG_COORD_ARRAY);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDeleteBuffers(1, &buf);
    }

    /* GL_EXP2 through a display list; then the current coordinate alone. */
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.3f);
    {
        GLuint list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glColor3f(0.9f, 0.3f, 0.6f);
        const float f[4] = {0.5f, 4.5f, 1.0f, 3.0f};
        quad(5, 122, 45, 33, f);
        glEndList();
        glCallList(list);
        glDeleteLists(list, 1);
        glFogCoordf(2.2f);
        glColor3f(0.2f, 0.9f, 0.9f);
        glRectf(58, 122, 100, 155);
        glFogCoordf(-1.1f);
        glRectf(108, 122, 155, 155);
    }
    scene_readpixels_check();
    return scene_end();
}
