/* Every glVertex{2,3,4}{s,i,f,d}[v] entry point draws one smooth triangle in
 * its own 32x32 cell (4-component forms use w != 1). */
#include "scene.h"

static const int P[3][2] = {{2, 2}, {30, 5}, {9, 29}};
static const GLubyte pal[5][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {255, 0, 255}};
static int cell, ox, oy;

#define X(i) (ox + P[i][0])
#define Y(i) (oy + P[i][1])
#define Z(i) ((i) - 1)                  /* -1, 0, 1 */
/* one triangle; the statement after it is executed for i = 0, 1, 2 */
#define TRI(...)                                                   \
    do {                                                           \
        int i;                                                     \
        ox = (cell % 6) * 32;                                      \
        oy = (cell / 6) * 32;                                      \
        glBegin(GL_TRIANGLES);                                     \
        for (i = 0; i < 3; i++) {                                  \
            glColor3ubv(pal[(i + cell) % 5]);                      \
            __VA_ARGS__;                                           \
        }                                                          \
        glEnd();                                                   \
        cell++;                                                    \
    } while (0)

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 128);
    scene_ortho_pixels();
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    TRI(glVertex2s((GLshort)X(i), (GLshort)Y(i)));
    TRI(GLshort v[2] = {(GLshort)X(i), (GLshort)Y(i)}; glVertex2sv(v));
    TRI(glVertex2i(X(i), Y(i)));
    TRI(GLint v[2] = {X(i), Y(i)}; glVertex2iv(v));
    TRI(glVertex2f(X(i) + 0.25f, Y(i) + 0.5f));
    TRI(GLfloat v[2] = {X(i) + 0.75f, Y(i) + 0.125f}; glVertex2fv(v));
    TRI(glVertex2d(X(i) + 0.375, Y(i) + 0.625));
    TRI(GLdouble v[2] = {X(i) + 0.1, Y(i) + 0.9}; glVertex2dv(v));

    TRI(glVertex3s((GLshort)X(i), (GLshort)Y(i), (GLshort)Z(i)));
    TRI(GLshort v[3] = {(GLshort)X(i), (GLshort)Y(i), (GLshort)Z(i)}; glVertex3sv(v));
    TRI(glVertex3i(X(i), Y(i), Z(i)));
    TRI(GLint v[3] = {X(i), Y(i), Z(i)}; glVertex3iv(v));
    TRI(glVertex3f(X(i) + 0.5f, Y(i) + 0.25f, Z(i) * 0.5f));
    TRI(GLfloat v[3] = {X(i) + 0.2f, Y(i) + 0.7f, Z(i) * 0.9f}; glVertex3fv(v));
    TRI(glVertex3d(X(i) + 0.6, Y(i) + 0.3, Z(i) * 0.25));
    TRI(GLdouble v[3] = {X(i) + 0.45, Y(i) + 0.55, Z(i) * 0.75}; glVertex3dv(v));

    TRI(glVertex4s((GLshort)(2 * X(i)), (GLshort)(2 * Y(i)), (GLshort)Z(i), 2));
    TRI(GLshort v[4] = {(GLshort)(3 * X(i)), (GLshort)(3 * Y(i)), 0, 3}; glVertex4sv(v));
    TRI(glVertex4i(2 * X(i) + 1, 2 * Y(i) + 1, Z(i), 2));
    TRI(GLint v[4] = {4 * X(i), 4 * Y(i), 2 * Z(i), 4}; glVertex4iv(v));
    TRI(glVertex4f((X(i) + 0.5f) * 0.5f, (Y(i) + 0.25f) * 0.5f, Z(i) * 0.25f, 0.5f));
    TRI(GLfloat v[4] = {X(i) * 1.5f, Y(i) * 1.5f, 0.0f, 1.5f}; glVertex4fv(v));
    TRI(glVertex4d(X(i) * 0.25, Y(i) * 0.25, Z(i) * 0.2, 0.25));
    TRI(GLdouble v[4] = {(X(i) + 0.3) * 2.5, (Y(i) + 0.6) * 2.5, Z(i) * 1.0, 2.5}; glVertex4dv(v));
    return scene_end();
}
