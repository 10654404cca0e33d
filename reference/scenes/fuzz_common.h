/* Shared by the fuzz_* scenes: the seeded generator of random legacy programs
 * (matrices, viewport, depth, cull, shading, lighting, material, glBegin/glEnd),
 * its logged GL wrappers and switches.  fuzz_random_state draws its operations
 * only from here (fuzz_core_op); fuzz_command_layer adds arrays, buffer objects,
 * attribute stacks and evaluators.  Any change here changes what
 * fuzz_random_state generates for a seed: keep the random draws in order. */
#ifndef GLFX_FUZZ_COMMON_H
#define GLFX_FUZZ_COMMON_H

#include "scene.h"
#include <stdio.h>
#include <stdlib.h>

#define FUZZ_W 160
#define FUZZ_H 120

static unsigned long long fz_state;
static int fz_log;
static int fz_inside;          /* between glBegin and glEnd */
static int fz_draw_index, fz_draw_lo, fz_draw_hi = 1 << 30;
static int fz_emit = 1;        /* current primitive is drawn */
static int fz_nolight;
static int fz_color3f;         /* GLFX_FUZZ_COLOR3F: use glColor3f (see top) */
static int fz_two_side;
static int fz_depth[2];        /* push depth: modelview, projection */
static int fz_mode;            /* 0 modelview, 1 projection */
static int fz_no_material;     /* set by fuzz_command_layer: glMaterial draws its random numbers but is not called (0 here) */

static unsigned fz_rand(void)
{
    fz_state = fz_state * 6364136223846793005ull + 1442695040888963407ull;
    return (unsigned)(fz_state >> 33);
}
static int fz_int(int n) { return (int)(fz_rand() % (unsigned)n); }
static float fz_f(float lo, float hi) { return lo + (hi - lo) * (float)(fz_rand() & 0xffffff) / 16777216.0f; }
static int fz_chance(int percent) { return fz_int(100) < percent; }

#define LOG(...) do { if (fz_log) { fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); } } while (0)

/* ---- logged GL wrappers ------------------------------------------------ */
static void L_Enable(GLenum c, int on)
{
    LOG("%s(0x%04X);", on ? "glEnable" : "glDisable", c);
    if (on) glEnable(c); else glDisable(c);
}
static void L_fv(const char *name, void (*fn)(GLenum, GLenum, const GLfloat *), GLenum a, GLenum p, const float *v, int n)
{
    if (fz_log) {
        int i;
        fprintf(stderr, "{ GLfloat v[4] = {");
        for (i = 0; i < n; i++) fprintf(stderr, "%s%.9g", i ? ", " : "", v[i]);
        fprintf(stderr, "}; %s(0x%04X, 0x%04X, v); }\n", name, a, p);
    }
    fn(a, p, v);
}
static void L_Color(void)
{
    float r = fz_f(0, 1), g = fz_f(0, 1), b = fz_f(0, 1), a = fz_f(0.2f, 1);
    int kind = fz_int(5);
    if (kind == 0) {
        GLubyte R = (GLubyte)fz_int(256), G = (GLubyte)fz_int(256), B = (GLubyte)fz_int(256);
        LOG("glColor3ub(%u, %u, %u);", R, G, B);
        glColor3ub(R, G, B);
    } else if (kind == 1 && fz_color3f) {
        LOG("glColor3f(%.9g, %.9g, %.9g);", r, g, b);
        glColor3f(r, g, b);
    } else if (kind == 1) {
        LOG("glColor3d(%.9g, %.9g, %.9g);", r, g, b);
        glColor3d(r, g, b);
    } else if (kind == 2 && fz_chance(20)) {
        /* out of range: clamped */
        r = fz_f(-0.5f, 1.5f); g = fz_f(-0.5f, 1.5f);
        LOG("glColor4f(%.9g, %.9g, %.9g, %.9g);", r, g, b, a);
        glColor4f(r, g, b, a);
    } else {
        LOG("glColor4f(%.9g, %.9g, %.9g, %.9g);", r, g, b, a);
        glColor4f(r, g, b, a);
    }
}
static void L_Normal(void)
{
    float x = fz_f(-1, 1), y = fz_f(-1, 1), z = fz_f(-0.3f, 1);
    if (fz_chance(30)) { x *= 3; y *= 3; z *= 3; }   /* not unit length */
    LOG("glNormal3f(%.9g, %.9g, %.9g);", x, y, z);
    glNormal3f(x, y, z);
}

static void rand_color4(float *v, float lo, float hi)
{
    v[0] = fz_f(lo, hi); v[1] = fz_f(lo, hi); v[2] = fz_f(lo, hi); v[3] = fz_f(0.3f, 1);
}

static const GLenum mat_pnames[] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE };

static void L_Material(int inside)
{
    GLenum face;
    GLenum pname = mat_pnames[fz_int(6)];
    float v[4];
    int f = fz_int(3);
    face = f == 0 ? GL_FRONT : f == 1 ? GL_BACK : GL_FRONT_AND_BACK;
    if (inside) face = GL_FRONT_AND_BACK;   /* known Mesa bug, see top */
    if (pname == GL_SHININESS) {
        v[0] = fz_f(0, 128);
        if (!fz_no_material) L_fv("glMaterialfv", glMaterialfv, face, pname, v, 1);
        return;
    }
    rand_color4(v, pname == GL_EMISSION ? 0.0f : 0.0f, pname == GL_EMISSION ? 0.4f : 1.0f);
    if (fz_chance(5)) v[0] = -0.3f;
    if (!fz_no_material) L_fv("glMaterialfv", glMaterialfv, face, pname, v, 4);
}

static void L_Light(void)
{
    GLenum light = GL_LIGHT0 + (GLenum)fz_int(8);
    float v[4];
    switch (fz_int(10)) {
    case 0: rand_color4(v, 0, 0.5f); L_fv("glLightfv", glLightfv, light, GL_AMBIENT, v, 4); break;
    case 1: case 2: rand_color4(v, 0, 1.2f); L_fv("glLightfv", glLightfv, light, GL_DIFFUSE, v, 4); break;
    case 3: rand_color4(v, 0, 1); L_fv("glLightfv", glLightfv, light, GL_SPECULAR, v, 4); break;
    case 4: case 5:
        v[0] = fz_f(-2, 2); v[1] = fz_f(-2, 2); v[2] = fz_f(-2, 3);
        v[3] = fz_chance(50) ? 0.0f : 1.0f;
        L_fv("glLightfv", glLightfv, light, GL_POSITION, v, 4);
        break;
    case 6:
        v[0] = fz_f(-1, 1); v[1] = fz_f(-1, 1); v[2] = fz_f(-1, 0.5f); v[3] = 0;
        L_fv("glLightfv", glLightfv, light, GL_SPOT_DIRECTION, v, 3);
        break;
    case 7:
        v[0] = fz_chance(30) ? 180.0f : fz_f(5, 90);
        L_fv("glLightfv", glLightfv, light, GL_SPOT_CUTOFF, v, 1);
        break;
    case 8:
        v[0] = fz_f(0, 64);
        L_fv("glLightfv", glLightfv, light, GL_SPOT_EXPONENT, v, 1);
        break;
    default: {
        int k = fz_int(3);
        v[0] = k == 0 ? fz_f(0.3f, 2) : k == 1 ? fz_f(0, 1) : fz_f(0, 0.5f);
        L_fv("glLightfv", glLightfv, light, k == 0 ? GL_CONSTANT_ATTENUATION : k == 1 ? GL_LINEAR_ATTENUATION : GL_QUADRATIC_ATTENUATION, v, 1);
        break;
    }
    }
}

static void L_LightModel(void)
{
    float v[4];
    switch (fz_int(4)) {
    case 0: rand_color4(v, 0, 0.4f);
        LOG("{ GLfloat v[4] = {%.9g, %.9g, %.9g, %.9g}; glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v); }", v[0], v[1], v[2], v[3]);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v);
        break;
    case 1: { int on = fz_int(2); LOG("glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, %d);", on); glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, on); break; }
    case 2: { int on = fz_int(2); LOG("glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, %d);", on); glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, on); fz_two_side = on; break; }
    default: {
        GLenum c = fz_int(2) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR;
        LOG("glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, 0x%04X);", c);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, (GLint)c);
        break;
    }
    }
}

/* ---- primitives --------------------------------------------------------- */
static const char *fz_draw_list;   /* GLFX_FUZZ_DRAWS: only these primitives */

/* Whether primitive i is drawn: inside GLFX_FUZZ_DRAW_LO..HI and, when
 * GLFX_FUZZ_DRAWS="a,b,..." is given, one of those. */
static int fz_draw_wanted(int i)
{
    const char *s = fz_draw_list;
    if (i < fz_draw_lo || i > fz_draw_hi) return 0;
    if (!s || !*s) return 1;
    while (*s) {
        char *end;
        long v = strtol(s, &end, 10);
        if (end == s) break;
        if (v == i) return 1;
        s = *end ? end + 1 : end;
    }
    return 0;
}

static float fz_cx, fz_cy, fz_cz;   /* random walk centre */

static void vertex(void)
{
    float x, y, z;
    int far_out = fz_chance(8);
    x = fz_cx + fz_f(-0.6f, 0.6f);
    y = fz_cy + fz_f(-0.6f, 0.6f);
    z = fz_cz + fz_f(-0.5f, 0.5f);
    if (far_out) {               /* off-screen or behind the eye */
        int k = fz_int(3);
        if (k == 0) x *= 6; else if (k == 1) y *= 6; else z += fz_f(2.5f, 6);
    }
    if (fz_emit) {
        if (fz_chance(10)) {
            float w = fz_f(0.5f, 2);
            LOG("glVertex4f(%.9g, %.9g, %.9g, %.9g);", x * w, y * w, z * w, w);
            glVertex4f(x * w, y * w, z * w, w);
        } else {
            LOG("glVertex3f(%.9g, %.9g, %.9g);", x, y, z);
            glVertex3f(x, y, z);
        }
    } else if (fz_chance(10)) {
        (void)fz_f(0.5f, 2);   /* the same random numbers as a drawn vertex */
    }
}

static const GLenum prims[] = { GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };

static void draw_prim(void)
{
    GLenum mode = prims[fz_int(6)];
    int n, i, repeat = fz_chance(25) ? 1 + fz_int(3) : 1, r;
    for (r = 0; r < repeat; r++) {
        fz_emit = fz_draw_wanted(fz_draw_index);
        fz_draw_index++;
        n = fz_int(10);
        if (mode == GL_TRIANGLES || mode == GL_QUADS) n = fz_int(4) * (mode == GL_TRIANGLES ? 3 : 4) + (fz_chance(20) ? fz_int(3) : 0);
        fz_cx = fz_f(-1, 1); fz_cy = fz_f(-1, 1); fz_cz = fz_f(-0.8f, 0.8f);
        if (fz_emit) { LOG("glBegin(0x%04X);", mode); glBegin(mode); fz_inside = 1; }
        for (i = 0; i < n; i++) {
            int k = fz_int(10);
            if (k == 0) L_Color();
            else if (k == 1) L_Normal();
            else if (k == 2 && fz_chance(30)) L_Material(1);
            vertex();
        }
        if (fz_emit) { LOG("glEnd();"); glEnd(); fz_inside = 0; }
    }
    fz_emit = 1;
}

/* ---- matrices ------------------------------------------------------------ */
static void set_mode(int m)
{
    fz_mode = m;
    LOG("glMatrixMode(%s);", m ? "GL_PROJECTION" : "GL_MODELVIEW");
    glMatrixMode(m ? GL_PROJECTION : GL_MODELVIEW);
}

static void projection(void)
{
    float n = fz_f(0.5f, 2), f = n + fz_f(2, 10), s = fz_f(0.3f, 1.2f), a = (float)FUZZ_W / FUZZ_H;
    set_mode(1);
    LOG("glLoadIdentity();"); glLoadIdentity();
    if (fz_chance(60)) {
        float dx = fz_f(-0.2f, 0.2f) * s;
        LOG("glFrustum(%.9g, %.9g, %.9g, %.9g, %.9g, %.9g);", -s * a * n + dx, s * a * n + dx, -s * n, s * n, n, f);
        glFrustum(-s * a * n + dx, s * a * n + dx, -s * n, s * n, n, f);
    } else {
        s = fz_f(1, 2.5f);
        LOG("glOrtho(%.9g, %.9g, %.9g, %.9g, %.9g, %.9g);", -s * a, s * a, -s, s, n, f);
        glOrtho(-s * a, s * a, -s, s, n, f);
    }
    set_mode(0);
    LOG("glLoadIdentity();"); glLoadIdentity();
    LOG("glTranslatef(0, 0, -3.5f);"); glTranslatef(0, 0, -3.5f);
}

static void matrix_op(void)
{
    int k = fz_int(9);
    float x = fz_f(-0.5f, 0.5f), y = fz_f(-0.5f, 0.5f), z = fz_f(-0.5f, 0.5f);
    switch (k) {
    case 0: case 1:
        LOG("glTranslatef(%.9g, %.9g, %.9g);", x, y, z); glTranslatef(x, y, z); break;
    case 2: case 3: {
        float ang = fz_f(-180, 180);
        LOG("glRotatef(%.9g, %.9g, %.9g, %.9g);", ang, x, y, z + 0.01f); glRotatef(ang, x, y, z + 0.01f); break;
    }
    case 4: {
        float sx = fz_f(0.5f, 1.5f), sy = fz_f(0.5f, 1.5f), sz = fz_f(0.5f, 1.5f);
        if (fz_chance(20)) sx = -sx;   /* mirror: flips the winding */
        if (fz_chance(50)) sy = sz = sx;
        LOG("glScalef(%.9g, %.9g, %.9g);", sx, sy, sz); glScalef(sx, sy, sz); break;
    }
    case 5:
        if (fz_depth[fz_mode] < (fz_mode ? 1 : 6)) { fz_depth[fz_mode]++; LOG("glPushMatrix();"); glPushMatrix(); }
        break;
    case 6:
        if (fz_depth[fz_mode] > 0) { fz_depth[fz_mode]--; LOG("glPopMatrix();"); glPopMatrix(); }
        break;
    case 7:
        set_mode(fz_int(4) == 0);
        break;
    default:
        if (fz_chance(30)) projection();
        break;
    }
}

static void viewport(void)
{
    int x = 0, y = 0, w = FUZZ_W, h = FUZZ_H;
    if (fz_chance(60)) {
        w = 20 + fz_int(FUZZ_W + 40); h = 20 + fz_int(FUZZ_H + 40);
        x = fz_int(FUZZ_W) - 40; y = fz_int(FUZZ_H) - 40;
    }
    LOG("glViewport(%d, %d, %d, %d);", x, y, w, h);
    glViewport(x, y, w, h);
}

/* ---- state ops -------------------------------------------------------------- */
static const GLenum depth_funcs[] = { GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS };
static const GLenum cm_modes[] = { GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE };

static void state_op(void)
{
    switch (fz_int(16)) {
    case 0: L_Enable(GL_DEPTH_TEST, fz_chance(80)); break;
    case 1: L_Enable(GL_CULL_FACE, fz_chance(40)); break;
    case 2: L_Enable(GL_LIGHTING, !fz_nolight && fz_chance(70)); break;
    case 3: L_Enable(GL_LIGHT0 + (GLenum)fz_int(8), fz_chance(70)); break;
    case 4: L_Enable(GL_COLOR_MATERIAL, fz_chance(50)); break;
    case 5: L_Enable(fz_int(2) ? GL_NORMALIZE : GL_RESCALE_NORMAL, fz_chance(50)); break;
    case 6: { GLenum f = depth_funcs[fz_chance(50) ? 1 + 2 * fz_int(2) : fz_int(8)]; LOG("glDepthFunc(0x%04X);", f); glDepthFunc(f); break; }
    case 7: { int m = fz_chance(75); LOG("glDepthMask(%d);", m); glDepthMask((GLboolean)m); break; }
    case 8: { int f = fz_int(3); GLenum c = f == 0 ? GL_FRONT : f == 1 ? GL_BACK : GL_FRONT_AND_BACK; LOG("glCullFace(0x%04X);", c); glCullFace(c); break; }
    case 9: { GLenum c = fz_int(2) ? GL_CW : GL_CCW; LOG("glFrontFace(0x%04X);", c); glFrontFace(c); break; }
    case 10: { GLenum c = fz_int(2) ? GL_FLAT : GL_SMOOTH; LOG("glShadeModel(0x%04X);", c); glShadeModel(c); break; }
    case 11: { GLenum c = fz_int(2) ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION; LOG("glProvokingVertex(0x%04X);", c); glProvokingVertex(c); break; }
    case 12: {
        GLenum face = fz_int(2) ? GL_FRONT : GL_FRONT_AND_BACK;   /* never GL_BACK: known Mesa bug */
        GLenum m = cm_modes[fz_int(5)];
        LOG("glColorMaterial(0x%04X, 0x%04X);", face, m);
        glColorMaterial(face, m);
        break;
    }
    case 13: {
        double n = fz_f(0, 1), f = fz_f(0, 1);
        if (fz_chance(50)) { n = 0; f = 1; }
        LOG("glDepthRange(%.9g, %.9g);", n, f);
        glDepthRange(n, f);
        break;
    }
    case 14: viewport(); break;
    default: if (fz_chance(50)) L_Color(); else L_Normal(); break;
    }
}

static void clear_op(void)
{
    GLbitfield m = (GLbitfield)(fz_chance(60) ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT : fz_chance(50) ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT);
    double d = fz_chance(70) ? 1.0 : fz_f(0.5f, 1);
    LOG("glClearDepth(%.9g); glClear(0x%X);", d, m);
    glClearDepth(d);
    glClear(m);
}

static int env_int(const char *name, int def)
{
    const char *s = getenv(name);
    return s && *s ? atoi(s) : def;
}


/* One operation of fuzz_random_state's mix, k in 0..99. */
static void fuzz_core_op(int k)
{
    if (k < 40) draw_prim();
    else if (k < 57) state_op();
    else if (k < 67) L_Light();
    else if (k < 71) L_LightModel();
    else if (k < 79) L_Material(0);
    else if (k < 98) matrix_op();
    else clear_op();
}

/* Reads the switches, seeds the generator, begins the scene and makes the
 * opening calls (projection, depth test, maybe lighting).  Returns the
 * number of operations to run (GLFX_FUZZ_MAXOPS caps it). */
static int fuzz_begin(int argc, char **argv, unsigned default_seed)
{
    unsigned seed = (unsigned)env_int("GLFX_FUZZ_SEED", (int)default_seed);
    int maxops = env_int("GLFX_FUZZ_MAXOPS", 1 << 30);
    int nops;
    fz_log = env_int("GLFX_FUZZ_LOG", 0);
    fz_draw_lo = env_int("GLFX_FUZZ_DRAW_LO", 0);
    fz_draw_hi = env_int("GLFX_FUZZ_DRAW_HI", 1 << 30);
    fz_draw_list = getenv("GLFX_FUZZ_DRAWS");
    fz_nolight = env_int("GLFX_FUZZ_NOLIGHT", 0);
    fz_color3f = env_int("GLFX_FUZZ_COLOR3F", 0);
    fz_state = seed * 2654435761ull + 12345;
    fz_rand(); fz_rand();

    scene_begin(argc, argv, FUZZ_W, FUZZ_H);
    LOG("/* seed %u */", seed);
    projection();
    LOG("glEnable(GL_DEPTH_TEST);"); glEnable(GL_DEPTH_TEST);
    if (!fz_nolight && fz_chance(60)) {
        L_Enable(GL_LIGHTING, 1);
        L_Enable(GL_LIGHT0, 1);
    }
    nops = 60 + fz_int(80);
    return nops < maxops ? nops : maxops;
}

static int fuzz_end(void)
{
    LOG("/* end */");
    return scene_end();
}

#endif
