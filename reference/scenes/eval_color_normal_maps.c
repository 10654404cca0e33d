/* Colour, normal and texture-coordinate maps: MAP2_COLOR_4 unlit and through GL_COLOR_MATERIAL, MAP2_NORMAL lit (alone and overridden by GL_AUTO_NORMAL), MAP1 colour/normal maps on a glEvalCoord1 fan; 64x64 cells. */
#include "light_common.h"

static const GLfloat kSheet[3][3][3] = {
    {{-1.0f, -1.0f, 0.2f}, {-1.0f, 0.0f, -0.4f}, {-1.0f, 1.0f, 0.1f}},
    {{0.0f, -1.0f, 0.5f}, {0.1f, 0.1f, 0.9f}, {0.0f, 1.0f, -0.3f}},
    {{1.0f, -1.0f, -0.2f}, {1.0f, 0.0f, 0.4f}, {1.0f, 1.0f, 0.3f}}};
/* 3x2 colours (uorder 3, vorder 2), alpha varying too */
static const GLfloat kColors[3][2][4] = {
    {{1.0f, 0.1f, 0.1f, 1.0f}, {0.1f, 0.2f, 1.0f, 0.6f}},
    {{0.2f, 1.0f, 0.3f, 0.8f}, {1.0f, 1.0f, 0.1f, 1.0f}},
    {{0.9f, 0.2f, 0.9f, 0.5f}, {0.1f, 0.9f, 0.9f, 1.0f}}};
/* 2x2 normals, not unit length */
static const GLfloat kNormals[2][2][3] = {
    {{-0.6f, -0.5f, 1.0f}, {-0.4f, 0.7f, 0.8f}},
    {{0.8f, -0.3f, 0.9f}, {0.5f, 0.6f, 1.2f}}};
static const GLfloat kTex[2][2][2] = {{{0, 0}, {0, 1}}, {{1, 0}, {1, 1}}};

static void cell(int i)
{
    light_cell(i, 3, 2, 64, 64);
    light_ortho(1.3f, 1.0f);
    glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(15.0f + 10.0f * (float)i, 0.0f, 0.0f, 1.0f);
}

static void mesh(void)
{
    glMapGrid2f(10, 0.0f, 1.0f, 9, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 10, 0, 9);
}

int main(int argc, char **argv)
{
    int i;
    scene_begin(argc, argv, 192, 128);
    glEnable(GL_DEPTH_TEST);
    light_all_black();
    light_model_ambient(0.2f, 0.2f, 0.2f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.5f, 0.4f, 1.0f, 0.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.5f, 0.5f, 0.5f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.7f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12.0f);
    glEnable(GL_LIGHT0);

    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 9, 3, 0.0f, 1.0f, 3, 3, &kSheet[0][0][0]);
    glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 8, 3, 0.0f, 1.0f, 4, 2, &kColors[0][0][0]);
    glMap2f(GL_MAP2_NORMAL, 0.0f, 1.0f, 6, 2, 0.0f, 1.0f, 3, 2, &kNormals[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_2, 0.0f, 1.0f, 4, 2, 0.0f, 1.0f, 2, 2, &kTex[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);

    /* 0: the colour map, unlit, smooth */
    cell(0);
    glEnable(GL_MAP2_COLOR_4);
    mesh();
    /* 1: the same under GL_FLAT: each strip triangle takes its last vertex's colour */
    cell(1);
    glShadeModel(GL_FLAT);
    mesh();
    glShadeModel(GL_SMOOTH);
    /* 2: the colour map through GL_COLOR_MATERIAL, lit with GL_AUTO_NORMAL;
     * the texture coordinate map is enabled too (no texturing yet) */
    cell(2);
    glEnable(GL_LIGHTING);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    mesh();
    glDisable(GL_MAP2_TEXTURE_COORD_2);
    /* Mesa leaves the current colour undefined after a map first made it
     * vertex data (MESA_FACTS.md); set it, and so the tracked material, again. */
    glColor4f(0.8f, 0.7f, 0.3f, 1.0f);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_MAP2_COLOR_4);
    /* 3: the normal map, lit, not normalised */
    cell(3);
    glDisable(GL_AUTO_NORMAL);
    glEnable(GL_MAP2_NORMAL);
    mesh();
    /* 4: the normal map with GL_AUTO_NORMAL: the computed normal wins */
    cell(4);
    glEnable(GL_AUTO_NORMAL);
    mesh();
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_MAP2_NORMAL);
    /* 5: 1D maps: a lit fan of glEvalCoord1 points on a cubic curve, the
     * colour (material) and normal from MAP1 maps */
    {
        static const GLfloat curve[4][3] = {{-1.0f, -0.8f, 0.0f}, {-0.6f, 1.4f, 0.3f}, {0.9f, 1.2f, -0.2f}, {1.0f, -0.9f, 0.1f}};
        static const GLfloat colors[3][4] = {{1.0f, 0.3f, 0.2f, 1.0f}, {0.2f, 1.0f, 0.4f, 1.0f}, {0.3f, 0.3f, 1.0f, 1.0f}};
        cell(5);
        glMap1f(GL_MAP1_VERTEX_3, -2.0f, 3.0f, 3, 4, &curve[0][0]);
        glMap1f(GL_MAP1_COLOR_4, -2.0f, 3.0f, 4, 3, &colors[0][0]);
        glMap1d(GL_MAP1_NORMAL, -2.0, 3.0, 3, 2, (const GLdouble[]){-0.5, 0.3, 1.0, 0.6, -0.2, 0.9});
        glEnable(GL_MAP1_VERTEX_3);
        glEnable(GL_MAP1_COLOR_4);
        glEnable(GL_MAP1_NORMAL);
        glEnable(GL_COLOR_MATERIAL);
        glNormal3f(0.0f, 0.0f, 1.0f);
        glColor3f(0.8f, 0.8f, 0.8f);
        glBegin(GL_TRIANGLE_FAN);
        glVertex3f(0.0f, -0.6f, 0.0f); /* the centre: the current colour and normal */
        for (i = 0; i <= 24; i++)
            glEvalCoord1f(-2.0f + 5.0f * (float)i / 24.0f);
        glEnd();
    }
    scene_readpixels_check();
    return scene_end();
}
