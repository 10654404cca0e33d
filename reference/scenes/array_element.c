/* glArrayElement between glBegin and glEnd: each element is the glColor,
 * glNormal and glVertex commands of its arrays' types (so integer colours
 * convert as glColor converts them), lit and unlit, GL_TRIANGLES, GL_QUADS
 * and a GL_QUAD_STRIP, mixed with plain glVertex calls. */
#include "array_common.h"

static torus_mesh m;
static GLubyte col_ub[TORUS_VERTS][4];
static GLbyte col_b[TORUS_VERTS][3];
static GLshort col_s[TORUS_VERTS][4];
static GLbyte nrm_b[TORUS_VERTS][3];
static GLdouble pos_d[TORUS_VERTS][3];

int main(int argc, char **argv)
{
    int i, j, k, u, v, cell = 0;
    scene_begin(argc, argv, 160, 120);
    array_lit_setup();
    torus_build(&m, 0.45f, 0.18f);
    for (i = 0; i < TORUS_VERTS; i++)
        for (j = 0; j < 4; j++) {
            col_ub[i][j] = (GLubyte)(m.col[i][j] * 255 + 0.5f);
            col_s[i][j] = (GLshort)(m.col[i][j] * 32767);
            if (j < 3) {
                col_b[i][j] = (GLbyte)(m.col[i][j] * 127);
                nrm_b[i][j] = (GLbyte)(m.nrm[i][j] * 127);
                pos_d[i][j] = m.pos[i][j];
            }
        }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, m.pos);
    for (int pass = 0; pass < 2; pass++) {
        /* lit: float normals, then byte normals with double positions */
        glNormalPointer(pass ? GL_BYTE : GL_FLOAT, 0, pass ? (void *)nrm_b : (void *)m.nrm);
        if (pass) glVertexPointer(3, GL_DOUBLE, 0, pos_d);
        array_cell(cell, 30.0f + 25 * cell); cell++;
        glBegin(GL_TRIANGLES);
        for (k = 0; k < m.tri_count; k++) glArrayElement(m.tri[k]);
        glEnd();
        array_cell(cell, 30.0f + 25 * cell); cell++;
        glBegin(GL_QUADS);
        for (k = 0; k < m.quad_count; k++) glArrayElement(m.quad[k]);
        glEnd();
    }
    glVertexPointer(3, GL_FLOAT, 0, m.pos);
    glNormalPointer(GL_FLOAT, 0, m.nrm);
    /* lit, colour material from a ubyte colour array, quad strips */
    glEnableClientState(GL_COLOR_ARRAY);
    glEnable(GL_COLOR_MATERIAL);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, col_ub);
    array_cell(cell, 30.0f + 25 * cell); cell++;
    for (u = 0; u < TORUS_NU; u++) {
        glBegin(GL_QUAD_STRIP);
        for (v = 0; v <= TORUS_NV; v++) {
            glArrayElement(torus_at(u, v));
            glArrayElement(torus_at(u + 1, v));
        }
        glEnd();
    }
    glDisable(GL_COLOR_MATERIAL);
    /* unlit: colour types */
    glDisable(GL_LIGHTING);
    glDisableClientState(GL_NORMAL_ARRAY);
    for (i = 0; i < 3; i++) {
        if (i == 0) glColorPointer(4, GL_UNSIGNED_BYTE, 0, col_ub);
        if (i == 1) glColorPointer(3, GL_BYTE, 0, col_b);
        if (i == 2) glColorPointer(4, GL_SHORT, 0, col_s);
        array_cell(cell, 30.0f + 25 * cell); cell++;
        glBegin(GL_TRIANGLES);
        for (k = 0; k < m.tri_count; k++) glArrayElement(m.tri[k]);
        glEnd();
    }
    /* mixed with plain vertices: the last element's colour is current */
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, col_ub);
    array_cell(cell, 30.0f + 25 * cell); cell++;
    glBegin(GL_TRIANGLES);
    for (k = 0; k < m.tri_count; k++) {
        if (k % 3 == 2) glVertex3fv(m.pos[m.tri[k]]);
        else glArrayElement(m.tri[k]);
    }
    glEnd();
    glDisableClientState(GL_COLOR_ARRAY);
    array_cell(cell, 30.0f + 25 * cell); cell++;
    glBegin(GL_TRIANGLES);
    for (k = 0; k < m.tri_count; k++) glArrayElement(m.tri[k]);
    glEnd();
    scene_readpixels_check();
    return scene_end();
}
