/* glEvalCoord and glEvalPoint inside glBegin/glEnd: quads at uneven parameters, evaluated and plain vertices in one glBegin, a colour map first making the colour vertex data mid-primitive, rational MAP1_VERTEX_4 arcs by glEvalPoint1, a lit quad strip, a clipped perspective mesh. */
#include "light_common.h"

static const GLfloat kSheet[3][3][3] = {
    {{-1.0f, -1.0f, 0.3f}, {-1.1f, 0.0f, -0.2f}, {-1.0f, 1.0f, 0.2f}},
    {{0.0f, -1.1f, -0.4f}, {0.0f, 0.0f, 0.8f}, {0.1f, 1.1f, -0.1f}},
    {{1.0f, -1.0f, 0.1f}, {1.1f, 0.1f, -0.3f}, {1.0f, 1.0f, 0.4f}}};
static const GLfloat kColors[2][2][4] = {
    {{1.0f, 0.2f, 0.1f, 1.0f}, {0.1f, 0.3f, 1.0f, 1.0f}},
    {{0.2f, 1.0f, 0.2f, 1.0f}, {1.0f, 0.9f, 0.2f, 1.0f}}};

static void cell(int i)
{
    light_cell(i, 3, 2, 64, 64);
    light_ortho(1.25f, 1.0f);
    glRotatef(10.0f * (float)i - 15.0f, 0.0f, 0.0f, 1.0f);
}

int main(int argc, char **argv)
{
    int i, j;
    scene_begin(argc, argv, 192, 128);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 9, 3, 0.0f, 1.0f, 3, 3, &kSheet[0][0][0]);
    glMap2f(GL_MAP2_COLOR_4, -1.0f, 1.0f, 8, 2, -1.0f, 1.0f, 4, 2, &kColors[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);

    /* 0: quads through glEvalCoord2 at uneven parameters, the colour map on */
    cell(0);
    glEnable(GL_MAP2_COLOR_4);
    glBegin(GL_QUADS);
    for (i = 0; i < 6; i++)
        for (j = 0; j < 5; j++) {
            float u0 = (float)(i * i) / 36.0f, u1 = (float)((i + 1) * (i + 1)) / 36.0f;
            float v0 = (float)j / 5.0f, v1 = (float)(j + 1) / 5.0f;
            glEvalCoord2f(u0, v0);
            glEvalCoord2f(u1, v0);
            glEvalCoord2f(u1, v1);
            glEvalCoord2f(u0, v1);
        }
    glEnd();

    /* 1: plain and evaluated vertices in one glBegin (the colour already
     * vertex data); then a colour map first making it vertex data after three
     * plain vertices: Mesa draws those at once, by themselves. */
    cell(1);
    glColor4f(0.9f, 0.9f, 0.9f, 1.0f);
    glBegin(GL_TRIANGLES);
    glColor4f(0.5f, 0.5f, 0.5f, 1.0f);
    glVertex3f(-1.0f, -1.0f, 0.0f);
    glVertex3f(-0.2f, -1.0f, 0.0f);
    glVertex3f(-1.0f, -0.2f, 0.0f);
    glEvalCoord2f(0.55f, 0.0f);
    glEvalCoord2f(1.0f, 0.0f);
    glEvalCoord2f(1.0f, 0.45f);
    glColor4f(0.3f, 0.6f, 0.9f, 1.0f);
    glVertex3f(-1.0f, 0.1f, 0.0f);
    glVertex3f(-0.1f, 0.1f, 0.0f);
    glVertex3f(-1.0f, 1.0f, 0.0f);
    glEnd();
    glTranslatef(0.0f, 0.0f, 0.0f); /* a state change: the colour is a constant again */
    glColor4f(0.8f, 0.4f, 0.1f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex3f(0.1f, 0.2f, 0.0f);
    glVertex3f(0.9f, 0.2f, 0.0f);
    glVertex3f(0.5f, 0.6f, 0.0f);
    glEvalCoord2f(0.6f, 0.7f);
    glEvalCoord2f(1.0f, 0.7f);
    glEvalCoord2f(1.0f, 1.0f);
    glEnd();
    glColor4f(0.8f, 0.4f, 0.1f, 1.0f); /* Mesa leaves the current colour undefined here (MESA_FACTS.md) */
    glDisable(GL_MAP2_COLOR_4);

    /* 2: rational quadratic arcs (MAP1_VERTEX_4) filled by glEvalPoint1
     * fans, coloured by a MAP1_COLOR_4; and glEvalPoint2 triangles */
    cell(2);
    {
        const float h = 0.70710678f;
        const GLfloat arc[3][4] = {{1.0f, 0.0f, 0.0f, 1.0f}, {h, h, 0.0f, h}, {0.0f, 1.0f, 0.0f, 1.0f}};
        const GLfloat colors[2][4] = {{1.0f, 0.3f, 0.2f, 1.0f}, {0.2f, 0.4f, 1.0f, 1.0f}};
        glMap1f(GL_MAP1_VERTEX_4, 0.0f, 1.0f, 4, 3, &arc[0][0]);
        glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &colors[0][0]);
        glEnable(GL_MAP1_VERTEX_4);
        glEnable(GL_MAP1_COLOR_4);
        glMapGrid1f(16, 0.0f, 1.0f);
        for (i = 0; i < 3; i++) {
            glPushMatrix();
            glRotatef(90.0f * (float)i, 0.0f, 0.0f, 1.0f);
            glScalef(1.1f, 1.1f, 1.0f);
            glBegin(GL_TRIANGLE_FAN);
            glVertex2f(0.0f, 0.0f);
            for (j = 0; j <= 16; j++)
                glEvalPoint1(j);
            glEnd();
            glPopMatrix();
        }
        glColor4f(0.9f, 0.8f, 0.2f, 1.0f);
        glMapGrid2f(5, 0.0f, 1.0f, 5, 0.0f, 1.0f);
        glBegin(GL_TRIANGLES);
        glEvalPoint2(0, 0);
        glEvalPoint2(2, 0);
        glEvalPoint2(0, 2);
        glEnd();
    }

    /* 3: a lit GL_AUTO_NORMAL surface as a quad strip of glEvalCoord2 points */
    cell(3);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 16.0f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glFrontFace(GL_CW); /* the side du x dv points out of */
    for (j = 0; j < 6; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 8; i++) {
            glEvalCoord2f((float)i / 8.0f, (float)j / 6.0f);
            glEvalCoord2f((float)i / 8.0f, (float)(j + 1) / 6.0f);
        }
        glEnd();
    }
    glFrontFace(GL_CCW);
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_LIGHTING);
    glNormal3f(0.0f, 0.0f, 1.0f);

    /* 4: a perspective mesh through the near plane, flat shaded, coloured by the map */
    light_cell(4, 3, 2, 64, 64);
    light_frustum(0.5f, 1.0f, 1.0f, 10.0f);
    glTranslatef(0.0f, -0.3f, -1.6f);
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_MAP2_COLOR_4);
    glMapGrid2f(6, 0.0f, 1.0f, 6, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 6, 0, 6);
    glShadeModel(GL_SMOOTH);

    /* 5: empty meshes, then a whole one in the map's colours over a grid
     * past the map's domain, smooth */
    cell(5);
    glEvalMesh2(GL_FILL, 3, 2, 0, 4);
    glEvalMesh2(GL_FILL, 0, 4, 2, 2);
    glMapGrid2f(4, -0.25f, 1.25f, 3, 1.2f, -0.2f);
    glEvalMesh2(GL_FILL, 0, 4, 0, 3);
    scene_readpixels_check();
    return scene_end();
}
