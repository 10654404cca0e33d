/* Every glColor{3,4}{b,s,i,f,d,ub,us,ui}[v] entry point: a smooth triangle
 * and a flat square per 24x24 cell, with values that expose the integer ->
 * float conversion rules (signed types, rounding at half, clamping). */
#include "scene.h"
#include <limits.h>

static int cell;
static float ox, oy;

static void next_cell(void)
{
    ox = (float)((cell % 8) * 24);
    oy = (float)((cell / 8) * 24);
    cell++;
}
static void v(int i)   /* vertex i of the smooth triangle */
{
    static const float p[3][2] = {{1, 1}, {23, 3}, {6, 23}};
    glVertex2f(ox + p[i][0], oy + p[i][1]);
}
static void square(void)   /* flat square, colour of its last vertex */
{
    glVertex2f(ox + 15, oy + 15); glVertex2f(ox + 23, oy + 15);
    glVertex2f(ox + 23, oy + 23); glVertex2f(ox + 15, oy + 23);
}

/* one cell: COLOR3(k) sets colour k of the tables below with one variant */
#define CELL(COLOR3)                                                 \
    do {                                                             \
        next_cell();                                                 \
        glShadeModel(GL_SMOOTH);                                     \
        glBegin(GL_TRIANGLES);                                       \
        COLOR3(0); v(0); COLOR3(1); v(1); COLOR3(2); v(2);           \
        glEnd();                                                     \
        glShadeModel(GL_FLAT);                                       \
        glBegin(GL_QUADS);                                           \
        COLOR3(3); square();                                         \
        glEnd();                                                     \
    } while (0)

/* value tables: [set][channel] */
static const GLbyte  tb[4][4] = {{127, 0, 64, 127}, {0, 127, -20, 64}, {33, 100, 127, 0}, {63, 64, 1, 32}};
static const GLshort ts[4][4] = {{32767, 0, 16384, 32767}, {0, 32767, -1000, 16383}, {12000, 30000, 32767, 0}, {16383, 16384, 128, 8192}};
static const GLint   ti[4][4] = {{INT_MAX, 0, INT_MAX / 2, INT_MAX}, {0, INT_MAX, -5, INT_MAX / 4},
                                 {700000000, 1900000000, INT_MAX, 0}, {INT_MAX / 2 + 1, 1 << 24, 8388608, 1 << 30}};
static const GLfloat tf[4][4] = {{1, 0, 0.5f, 1}, {0, 1, -0.2f, 0.5f}, {0.3f, 0.8f, 1.2f, 0}, {0.5f / 255, 1.5f / 255, 127.5f / 255, 0.25f}};
static const GLdouble td[4][4] = {{0.25, 0.75, 1, 1}, {1, 0.125, 0, 0.5}, {0.6, 0.2, 0.9, 0}, {2.5 / 255, 128.5 / 255, 254.5 / 255, 0.75}};
static const GLubyte tub[4][4] = {{255, 0, 128, 255}, {0, 255, 1, 127}, {77, 200, 255, 0}, {127, 128, 129, 64}};
static const GLushort tus[4][4] = {{65535, 0, 32768, 65535}, {0, 65535, 257, 32767}, {20000, 50000, 65535, 0}, {32767, 32768, 128, 16384}};
static const GLuint  tui[4][4] = {{UINT_MAX, 0, UINT_MAX / 2 + 1, UINT_MAX}, {0, UINT_MAX, 5, UINT_MAX / 2},
                                  {1000000000u, 3000000000u, UINT_MAX, 0}, {UINT_MAX / 2, 16777216u, 2147483648u, 1u << 30}};

#define C3b(k)   glColor3b(tb[k][0], tb[k][1], tb[k][2])
#define C3bv(k)  glColor3bv(tb[k])
#define C4b(k)   glColor4b(tb[k][0], tb[k][1], tb[k][2], tb[k][3])
#define C4bv(k)  glColor4bv(tb[k])
#define C3s(k)   glColor3s(ts[k][0], ts[k][1], ts[k][2])
#define C3sv(k)  glColor3sv(ts[k])
#define C4s(k)   glColor4s(ts[k][0], ts[k][1], ts[k][2], ts[k][3])
#define C4sv(k)  glColor4sv(ts[k])
#define C3i(k)   glColor3i(ti[k][0], ti[k][1], ti[k][2])
#define C3iv(k)  glColor3iv(ti[k])
#define C4i(k)   glColor4i(ti[k][0], ti[k][1], ti[k][2], ti[k][3])
#define C4iv(k)  glColor4iv(ti[k])
#define C3f(k)   glColor3f(tf[k][0], tf[k][1], tf[k][2])
#define C3fv(k)  glColor3fv(tf[k])
#define C4f(k)   glColor4f(tf[k][0], tf[k][1], tf[k][2], tf[k][3])
#define C4fv(k)  glColor4fv(tf[k])
#define C3d(k)   glColor3d(td[k][0], td[k][1], td[k][2])
#define C3dv(k)  glColor3dv(td[k])
#define C4d(k)   glColor4d(td[k][0], td[k][1], td[k][2], td[k][3])
#define C4dv(k)  glColor4dv(td[k])
#define C3ub(k)  glColor3ub(tub[k][0], tub[k][1], tub[k][2])
#define C3ubv(k) glColor3ubv(tub[k])
#define C4ub(k)  glColor4ub(tub[k][0], tub[k][1], tub[k][2], tub[k][3])
#define C4ubv(k) glColor4ubv(tub[k])
#define C3us(k)  glColor3us(tus[k][0], tus[k][1], tus[k][2])
#define C3usv(k) glColor3usv(tus[k])
#define C4us(k)  glColor4us(tus[k][0], tus[k][1], tus[k][2], tus[k][3])
#define C4usv(k) glColor4usv(tus[k])
#define C3ui(k)  glColor3ui(tui[k][0], tui[k][1], tui[k][2])
#define C3uiv(k) glColor3uiv(tui[k])
#define C4ui(k)  glColor4ui(tui[k][0], tui[k][1], tui[k][2], tui[k][3])
#define C4uiv(k) glColor4uiv(tui[k])

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 96);
    scene_ortho_pixels();
    CELL(C3b);  CELL(C3bv);  CELL(C4b);  CELL(C4bv);
    CELL(C3s);  CELL(C3sv);  CELL(C4s);  CELL(C4sv);
    CELL(C3i);  CELL(C3iv);  CELL(C4i);  CELL(C4iv);
    CELL(C3f);  CELL(C3fv);  CELL(C4f);  CELL(C4fv);
    CELL(C3d);  CELL(C3dv);  CELL(C4d);  CELL(C4dv);
    CELL(C3ub); CELL(C3ubv); CELL(C4ub); CELL(C4ubv);
    CELL(C3us); CELL(C3usv); CELL(C4us); CELL(C4usv);
    CELL(C3ui); CELL(C3uiv); CELL(C4ui); CELL(C4uiv);
    scene_readpixels_check();
    return scene_end();
}
