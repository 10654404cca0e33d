/* The random evaluator cases both sides of the Mesa evaluator comparison
 * build: a tiny LCG, so that C (Mesa's side) and C++ (libglfixed's) agree. */
#ifndef GLFX_EVAL_CASES_H
#define GLFX_EVAL_CASES_H

typedef struct {
    unsigned state;
} eval_rng;

static float eval_rand01(eval_rng *r) /* in [0, 1), 24 random bits */
{
    r->state = r->state * 1664525u + 1013904223u;
    return (float)(r->state >> 8) / 16777216.0f;
}
static float eval_rand(eval_rng *r, float lo, float hi) { return lo + (hi - lo) * eval_rand01(r); }

enum { EVAL_CASES = 240, EVAL_COORDS = 24, EVAL_ROTATIONS = 3 };

/* One case: a 1D or 2D map of orders uorder x vorder on a domain, evaluated
 * at EVAL_COORDS parameters, with a VERTEX_3 map (points in [-0.9, 0.9]^3),
 * a COLOR_4 map (in [0.05, 0.95]), a TEXTURE_COORD_4 map (in [-4, 4]); the
 * 2D cases alternate GL_AUTO_NORMAL (the vertex then comes from de Casteljau). */
typedef struct {
    int two_d, auto_normal, uorder, vorder;
    float u1, u2, v1, v2;
    float vertex[30 * 30 * 3], color[30 * 30 * 4], tex[30 * 30 * 4];
    float u[EVAL_COORDS], v[EVAL_COORDS];
} eval_case;

static void eval_make_case(int n, eval_case *c)
{
    eval_rng r;
    int i, count;
    r.state = 0x9e3779b9u * (unsigned)(n + 1);
    c->two_d = n % 2;
    c->auto_normal = c->two_d && (n % 4 == 3);
    c->uorder = 1 + (int)(eval_rand01(&r) * (c->two_d ? 9.0f : 30.0f));
    c->vorder = c->two_d ? 1 + (int)(eval_rand01(&r) * 9.0f) : 1;
    if (c->auto_normal) { /* de Casteljau needs two points each way */
        if (c->uorder < 2) c->uorder = 2;
        if (c->vorder < 2) c->vorder = 2;
    }
    c->u1 = eval_rand(&r, -3.0f, 3.0f);
    c->u2 = c->u1 + (eval_rand01(&r) < 0.5f ? -1.0f : 1.0f) * eval_rand(&r, 0.25f, 4.0f);
    c->v1 = eval_rand(&r, -3.0f, 3.0f);
    c->v2 = c->v1 + (eval_rand01(&r) < 0.5f ? -1.0f : 1.0f) * eval_rand(&r, 0.25f, 4.0f);
    count = c->uorder * c->vorder;
    for (i = 0; i < count * 3; i++) c->vertex[i] = eval_rand(&r, -0.9f, 0.9f);
    for (i = 0; i < count * 4; i++) c->color[i] = eval_rand(&r, 0.05f, 0.95f);
    for (i = 0; i < count * 4; i++) c->tex[i] = eval_rand(&r, -4.0f, 4.0f);
    for (i = 0; i < EVAL_COORDS; i++) { /* inside the domain, its ends included */
        float a = i == 0 ? 0.0f : i == 1 ? 1.0f : eval_rand01(&r);
        float b = i == 0 ? 1.0f : i == 1 ? 0.0f : eval_rand01(&r);
        c->u[i] = c->u1 + a * (c->u2 - c->u1);
        c->v[i] = c->v1 + b * (c->v2 - c->v1);
    }
}

/* Rotation k of the vertex components (x, y, z) -> (y, z, x) k times, so that
 * every component passes through the exactly compared window x. */
static void eval_rotate_vertices(const eval_case *c, int k, float *out)
{
    int i, j, count = c->uorder * c->vorder;
    for (i = 0; i < count; i++)
        for (j = 0; j < 3; j++) out[i * 3 + j] = c->vertex[i * 3 + (j + k) % 3];
}

/* A grid case: glMapGrid over a random (possibly reversed) range, then
 * glEvalMesh(GL_POINT) over a random part of it (past its ends too) and a few
 * glEvalPoint: the parameter arithmetic of the grid commands. The map is the
 * case's VERTEX_3 map. */
typedef struct {
    int n, m, i1, i2, j1, j2;
    float gu1, gu2, gv1, gv2;
    int points[8][2];
} eval_grid;

enum { EVAL_GRIDS = 120 };

static void eval_make_grid(int n, eval_grid *g)
{
    eval_rng r;
    int i;
    r.state = 0x85ebca6bu * (unsigned)(n + 7);
    g->n = 1 + (int)(eval_rand01(&r) * 12.0f);
    g->m = 1 + (int)(eval_rand01(&r) * 12.0f);
    g->gu1 = eval_rand(&r, -3.0f, 3.0f);
    g->gu2 = eval_rand(&r, -3.0f, 3.0f);
    g->gv1 = eval_rand(&r, -3.0f, 3.0f);
    g->gv2 = eval_rand(&r, -3.0f, 3.0f);
    g->i1 = (int)(eval_rand01(&r) * 5.0f) - 2;
    g->i2 = g->i1 + (int)(eval_rand01(&r) * (float)(g->n + 3));
    g->j1 = (int)(eval_rand01(&r) * 5.0f) - 2;
    g->j2 = g->j1 + (int)(eval_rand01(&r) * (float)(g->m + 3));
    for (i = 0; i < 8; i++) {
        g->points[i][0] = (int)(eval_rand01(&r) * (float)(g->n + 5)) - 2;
        g->points[i][1] = (int)(eval_rand01(&r) * (float)(g->m + 5)) - 2;
    }
}

#endif
