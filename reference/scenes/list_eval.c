/* Evaluators compiled into display lists (§5.4): a lit Bézier patch whose
 * glMap2 (the control points copied at compile time), glMapGrid2 and
 * glEvalMesh2 are in a list, replayed after the program's points changed and
 * after the context's map was replaced; a strip of glEvalCoord2 and
 * glEvalPoint2 between a list's glBegin and glEnd, coloured by a
 * GL_MAP2_COLOR_4 (the vertex node ends there and the rest is compiled as
 * commands, as in Mesa's save module), after glVertex calls; and a
 * glEvalMesh2(GL_FILL) list made before any map exists. (Filled only: lines
 * and points are not rasterized yet.) (Not GL_COMPILE_AND_EXECUTE of a
 * glEvalMesh: Mesa compiles what the mesh issues as well, MESA_FACTS.) */
#include "light_common.h"

static GLfloat patch[4][4][3] = {
    {{-1.5f, -1.5f, 4.0f}, {-0.5f, -1.5f, 2.0f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 2.0f}},
    {{-1.5f, -0.5f, 1.0f}, {-0.5f, -0.5f, 3.0f}, {0.5f, -0.5f, 0.0f}, {1.5f, -0.5f, -1.0f}},
    {{-1.5f, 0.5f, 4.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}, {1.5f, 0.5f, 4.0f}},
    {{-1.5f, 1.5f, -2.0f}, {-0.5f, 1.5f, -2.0f}, {0.5f, 1.5f, 0.0f}, {1.5f, 1.5f, -1.0f}}};
static GLfloat curve_colors[2][3][4] = {{{1, 0.2f, 0.1f, 1}, {0.2f, 1, 0.3f, 1}, {0.1f, 0.3f, 1, 1}},
                                        {{1, 1, 0.1f, 1}, {0.2f, 0.3f, 0.3f, 1}, {0.9f, 0.3f, 1, 1}}};
enum { PATCH = 1, CURVE, WIRE };

int main(int argc, char **argv)
{
    int i, j;
    scene_begin(argc, argv, 192, 192);
    light_ortho(2.6f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.1f, 0.1f, 0.12f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.7f, 0.5f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.3f, 0.3f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.6f, 0.4f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glFrontFace(GL_CW);

    glNewList(PATCH, GL_COMPILE);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_LIGHTING);
    glMapGrid2f(16, 0.0f, 1.0f, 16, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 16, 0, 16);
    glDisable(GL_LIGHTING);
    glEndList();
    for (i = 0; i < 4; i++) /* the list copied the points: this must not show */
        for (j = 0; j < 4; j++) patch[i][j][2] = -patch[i][j][2];

    glNewList(CURVE, GL_COMPILE); /* a strip of the patch, coloured by a map */
    glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 4, 3, 0.0f, 1.0f, 12, 2, &curve_colors[0][0][0]);
    glEnable(GL_MAP2_COLOR_4);
    glMapGrid2f(12, 0.0f, 1.0f, 4, 0.0f, 0.3f);
    glBegin(GL_TRIANGLE_STRIP);
    glColor3f(1, 1, 1);
    glVertex3f(-1.6f, -1.6f, 0);
    glVertex3f(-1.6f, -0.4f, 0);
    for (i = 0; i <= 6; i++) { /* ends the vertex node: the rest are commands */
        glEvalCoord2f(i / 12.0f, 0.0f);
        glEvalCoord2f(i / 12.0f, 0.3f);
    }
    for (i = 6; i <= 12; i++) {
        glEvalPoint2(i, 0);
        glEvalPoint2(i, 4);
    }
    glEnd();
    glDisable(GL_MAP2_COLOR_4);
    glEndList();
    curve_colors[0][0][0] = 0.0f; /* not seen by the list */

    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glTranslatef(0.0f, 0.6f, -2.0f);
    glScalef(0.6f, 0.6f, 0.6f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glNewList(WIRE, GL_COMPILE);
    glColor3f(0.9f, 0.9f, 0.3f);
    glEvalMesh2(GL_FILL, 0, 8, 0, 8); /* with the map and grid in effect when it runs */
    glEndList();
    glPopMatrix();

    glPushMatrix();
    glTranslatef(-1.2f, 1.0f, -2.0f);
    glScalef(0.45f, 0.45f, 0.45f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glCallList(PATCH);
    glPopMatrix();
    /* the context's map replaced: the next replay restores the list's */
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glPushMatrix();
    glTranslatef(1.2f, 1.0f, -2.0f);
    glScalef(0.45f, 0.45f, 0.45f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glCallList(PATCH);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -2.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    glCallList(CURVE);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.0f, -0.4f, -2.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    glCallList(WIRE);
    glPopMatrix();
    return scene_end();
}
