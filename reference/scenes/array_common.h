/* Shared by the array_* and buffer_* scenes: one lit torus, tessellated here
 * into vertex, normal and colour arrays (a (nu+1) x (nv+1) grid), with index
 * lists for GL_TRIANGLES, GL_QUADS and per-ring GL_QUAD_STRIPs, and the light
 * and view every scene uses. */
#ifndef GLFX_ARRAY_COMMON_H
#define GLFX_ARRAY_COMMON_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "light_common.h"

#define TORUS_NU 24 /* around the ring */
#define TORUS_NV 12 /* around the tube */
#define TORUS_VERTS ((TORUS_NU + 1) * (TORUS_NV + 1))

typedef struct {
    float pos[TORUS_VERTS][3];
    float nrm[TORUS_VERTS][3];
    float col[TORUS_VERTS][4];
    unsigned int tri[TORUS_NU * TORUS_NV * 6];  /* GL_TRIANGLES */
    unsigned int quad[TORUS_NU * TORUS_NV * 4]; /* GL_QUADS */
    int tri_count, quad_count;
} torus_mesh;

static inline int torus_at(int u, int v) { return u * (TORUS_NV + 1) + v; }

static inline void torus_build(torus_mesh *m, float R, float r)
{
    int u, v, t = 0, q = 0;
    for (u = 0; u <= TORUS_NU; u++)
        for (v = 0; v <= TORUS_NV; v++) {
            float a = 6.2831853f * u / TORUS_NU, b = 6.2831853f * v / TORUS_NV;
            int i = torus_at(u, v);
            m->nrm[i][0] = cosf(a) * cosf(b);
            m->nrm[i][1] = sinf(a) * cosf(b);
            m->nrm[i][2] = sinf(b);
            m->pos[i][0] = (R + r * cosf(b)) * cosf(a);
            m->pos[i][1] = (R + r * cosf(b)) * sinf(a);
            m->pos[i][2] = r * sinf(b);
            m->col[i][0] = 0.5f + 0.5f * cosf(a);
            m->col[i][1] = 0.5f + 0.5f * sinf(b);
            m->col[i][2] = 0.5f + 0.5f * sinf(a);
            m->col[i][3] = 1.0f;
        }
    for (u = 0; u < TORUS_NU; u++)
        for (v = 0; v < TORUS_NV; v++) {
            unsigned a = torus_at(u, v), b = torus_at(u + 1, v), c = torus_at(u + 1, v + 1), d = torus_at(u, v + 1);
            m->tri[t++] = a; m->tri[t++] = b; m->tri[t++] = c;
            m->tri[t++] = a; m->tri[t++] = c; m->tri[t++] = d;
            m->quad[q++] = a; m->quad[q++] = b; m->quad[q++] = c; m->quad[q++] = d;
        }
    m->tri_count = t;
    m->quad_count = q;
}

/* A white light from the upper left, shiny material, colour material on the
 * diffuse and ambient terms (so a colour array changes the lighting), depth
 * test, perspective; the torus is drawn at (x, y) in a 4 x 4 grid of cells. */
static inline void array_lit_setup(void)
{
    light_frustum(0.5f, 1.0f, 2.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.7f, 1.0f, 0.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.7f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.7f, 0.6f, 0.3f, 1.0f);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
}

static inline void array_cell(int cell, float angle)
{
    float x = -1.5f + (cell % 4), y = 1.5f - (cell / 4);
    glLoadIdentity();
    glTranslatef(x * 1.25f, y * 1.25f, -10.0f);
    glRotatef(angle, 1.0f, 0.6f, 0.2f);
}

/* Expands an index list into plain arrays (for glDrawArrays). */
static inline void torus_expand(const torus_mesh *m, const unsigned *idx, int n, float *pos, float *nrm, float *col)
{
    int k;
    for (k = 0; k < n; k++) {
        memcpy(pos + 3 * k, m->pos[idx[k]], sizeof(float) * 3);
        memcpy(nrm + 3 * k, m->nrm[idx[k]], sizeof(float) * 3);
        memcpy(col + 4 * k, m->col[idx[k]], sizeof(float) * 4);
    }
}

#endif
