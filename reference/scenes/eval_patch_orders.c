/* Lit GL_AUTO_NORMAL patches of every shape of de Casteljau's evaluation: orders 2x2 to 10x4, reversed and offset domains, a partial mesh, a rational VERTEX_4 patch; one 64x64 cell each. */
#include "light_common.h"

/* A wavy sheet over [-1,1]^2 of uorder x vorder control points, packed with
 * v fastest (k values each, w = `weight` pattern for k = 4). */
static void sheet(GLfloat *p, int uorder, int vorder, int k, float phase)
{
    int i, j;
    for (i = 0; i < uorder; i++)
        for (j = 0; j < vorder; j++) {
            GLfloat *q = p + (i * vorder + j) * k;
            float x = -1.0f + 2.0f * (float)i / (float)(uorder - 1);
            float y = -1.0f + 2.0f * (float)j / (float)(vorder - 1);
            float z = 0.6f * sinf(1.7f * (float)i + 0.9f * (float)j + phase);
            float w = (k == 4) ? 1.0f + 0.8f * (float)((i + 2 * j) % 3) : 1.0f;
            q[0] = x * w;
            q[1] = y * w;
            q[2] = z * w;
            if (k == 4) q[3] = w;
        }
}

static void cell(int i)
{
    light_cell(i, 3, 3, 64, 64);
    light_ortho(1.45f, 1.0f);
    glRotatef(-40.0f + 7.0f * (float)i, 1.0f, 0.0f, 0.0f);
    glRotatef(25.0f - 11.0f * (float)i, 0.0f, 1.0f, 0.0f);
}

/* One patch: MAP2_VERTEX_k (k = 3 or 4) on domain [u1,u2]x[v1,v2], a grid of
 * n x m steps over [gu1,gu2]x[gv1,gv2], and the mesh i1..i2, j1..j2. */
static void patch(int k, int uorder, int vorder, float u1, float u2, float v1, float v2, float phase,
                  int n, float gu1, float gu2, int m, float gv1, float gv2, int i1, int i2, int j1, int j2)
{
    static GLfloat p[30 * 30 * 4];
    GLenum target = k == 4 ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3;
    sheet(p, uorder, vorder, k, phase);
    glMap2f(target, u1, u2, vorder * k, uorder, v1, v2, k, vorder, p);
    glDisable(GL_MAP2_VERTEX_3);
    glDisable(GL_MAP2_VERTEX_4);
    glEnable(target);
    glMapGrid2f(n, gu1, gu2, m, gv1, gv2);
    glEvalMesh2(GL_FILL, i1, i2, j1, j2);
}

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 192);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glFrontFace(GL_CW); /* du x dv faces the viewer where the strips wind clockwise */
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.7f, 0.7f, 0.7f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.6f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.4f, 0.5f, 0.9f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.3f, 0.5f, 0.9f, 1.0f);
    light_mat(GL_BACK, GL_AMBIENT, 0.9f, 0.5f, 0.3f, 1.0f);
    light_mat(GL_BACK, GL_DIFFUSE, 0.9f, 0.5f, 0.2f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);

    cell(0); patch(3, 2, 2, 0, 1, 0, 1, 0.3f, 6, 0, 1, 6, 0, 1, 0, 6, 0, 6);        /* bilinear */
    cell(1); patch(3, 3, 5, 0, 1, 0, 1, 0.0f, 12, 0, 1, 10, 0, 1, 0, 12, 0, 10);    /* uorder < vorder */
    cell(2); patch(3, 5, 3, 0, 1, 0, 1, 1.0f, 10, 0, 1, 12, 0, 1, 0, 10, 0, 12);    /* uorder > vorder */
    cell(3); patch(3, 4, 4, 1, 0, 0, 1, 2.0f, 12, 0, 1, 12, 0, 1, 0, 12, 0, 12);    /* reversed u domain */
    cell(4); patch(3, 6, 6, 2, 5, -1, 1, 0.7f, 9, 2, 5, 8, -1, 1, 2, 9, 0, 7);      /* offset domain, part of the grid */
    cell(5); patch(3, 2, 6, 0, 1, 1, -1, 1.5f, 8, 0, 1, 14, 1, -1, 0, 8, 0, 14);    /* 2 x 6, reversed v */
    cell(6); patch(4, 4, 3, 0, 1, 0, 1, 0.4f, 12, 0, 1, 12, 0, 1, 0, 12, 0, 12);    /* rational */
    cell(7); patch(3, 8, 2, 0, 1, 0, 1, 2.5f, 14, 0, 1, 6, 0, 1, 0, 14, 0, 6);      /* 8 x 2 */
    cell(8); patch(3, 10, 4, 0, 1, 0, 1, 0.9f, 15, -0.1f, 1.1f, 10, 0, 1, 1, 14, 0, 10); /* 10 x 4, grid past the domain */
    scene_readpixels_check();
    return scene_end();
}
