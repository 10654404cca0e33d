/* Random legacy program over every primitive of GL 2.1 (GLFX_FUZZ_SEED):
 * fuzz_random_state's mix, plus points and lines of every mode and the
 * per-primitive state of issue 12: point size, line width and stipple,
 * polygon modes per face, edge flags, polygon offset, polygon stipple, user
 * clip planes, the scissor test and colour masks. The generator only uses
 * what both sides define: no smooth points or lines unless
 * GLFX_FUZZ_SMOOTH=1 (antialiasing has its own scenes), and never different
 * polygon modes on the two faces with smoothing on (a Mesa defect,
 * REFERENCE.md). GLFX_FUZZ_PRIM_OPS=n keeps only the first n kinds of
 * primitive state operation (0-1 sizes, 2-3 line stipple, 4-8 polygons, 9-10
 * clip planes, 11-12 scissor, 13 colour mask). The switches of fuzz_random_state apply (GLFX_FUZZ_LOG=1
 * prints the program as C). */
#include "fuzz_common.h"

#define FUZZ_DEFAULT_SEED 7u

static int fz_smooth;
static int fz_emit_flags;   /* a glEdgeFlag was called in the current primitive */
static int fz_prim_ops = 14;  /* GLFX_FUZZ_PRIM_OPS=n: only the first n kinds of primitive_state_op */
static const GLenum all_prims[] = { GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES,
                                    GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON };

/* A glBegin/glEnd of any mode, with edge flags now and then. */
static void draw_any_prim(void)
{
    GLenum mode = all_prims[fz_int(10)];
    int n = 1 + fz_int(12), i;
    /* GL 2.1 ignores edge flags in strips and fans; Mesa applies them there
     * (REFERENCE.md), a defect not copied, so they go elsewhere only. */
    int flags_ok = mode != GL_TRIANGLE_STRIP && mode != GL_TRIANGLE_FAN && mode != GL_QUAD_STRIP;
    fz_emit = fz_draw_wanted(fz_draw_index);
    fz_draw_index++;
    fz_cx = fz_f(-1, 1); fz_cy = fz_f(-1, 1); fz_cz = fz_f(-0.8f, 0.8f);
    if (fz_emit) { LOG("glBegin(0x%04X);", mode); glBegin(mode); fz_inside = 1; }
    for (i = 0; i < n; i++) {
        int k = fz_int(12);
        if (k == 0) L_Color();
        else if (k == 1) L_Normal();
        else if (k == 2 && fz_emit && flags_ok) { int f = fz_int(2); LOG("glEdgeFlag(%d);", f); glEdgeFlag((GLboolean)f); fz_emit_flags = 1; }
        vertex();
    }
    if (fz_emit) { LOG("glEnd();"); glEnd(); fz_inside = 0; }
    fz_emit = 1;
    /* Back to GL_TRUE, so that no later strip or fan meets a false flag. */
    if (flags_ok && fz_emit_flags) { LOG("glEdgeFlag(1);"); glEdgeFlag(GL_TRUE); }
    fz_emit_flags = 0;
}

static const GLenum poly_modes[] = { GL_POINT, GL_LINE, GL_FILL };

static void primitive_state_op(void)
{
    int kind = fz_int(14);
    if (kind >= fz_prim_ops) return;
    switch (kind) {
    case 0: {
        float s = fz_chance(50) ? (float)(1 + fz_int(8)) : fz_f(0.5f, 12);
        LOG("glPointSize(%.9g);", s); glPointSize(s); break;
    }
    case 1: {
        float w = fz_chance(50) ? (float)(1 + fz_int(6)) : fz_f(0.5f, 8);
        LOG("glLineWidth(%.9g);", w); glLineWidth(w); break;
    }
    case 2: L_Enable(GL_LINE_STIPPLE, fz_chance(50)); break;
    case 3: {
        int f = 1 + fz_int(4); unsigned p = fz_rand() & 0xffff;
        LOG("glLineStipple(%d, 0x%04X);", f, p); glLineStipple(f, (GLushort)p); break;
    }
    case 4: {
        int f = fz_int(3); GLenum face = f == 0 ? GL_FRONT : f == 1 ? GL_BACK : GL_FRONT_AND_BACK;
        GLenum m = poly_modes[fz_int(3)];
        if (fz_smooth && face != GL_FRONT_AND_BACK) face = GL_FRONT_AND_BACK;
        LOG("glPolygonMode(0x%04X, 0x%04X);", face, m); glPolygonMode(face, m); break;
    }
    case 5: {
        float f = fz_f(-2, 4), u = fz_f(-4, 8);
        LOG("glPolygonOffset(%.9g, %.9g);", f, u); glPolygonOffset(f, u); break;
    }
    case 6: {
        int k = fz_int(3);
        L_Enable(k == 0 ? GL_POLYGON_OFFSET_FILL : k == 1 ? GL_POLYGON_OFFSET_LINE : GL_POLYGON_OFFSET_POINT, fz_chance(60));
        break;
    }
    case 7: {
        GLubyte mask[128]; int i;
        unsigned a = fz_rand(), b = fz_rand();
        for (i = 0; i < 128; i++) mask[i] = (GLubyte)(((i & 4) ? a : b) >> ((i * 3) & 24));
        LOG("/* glPolygonStipple(pattern from 0x%08X, 0x%08X) */", a, b);
        if (fz_log) {
            fprintf(stderr, "{ static const GLubyte m[128] = {");
            for (i = 0; i < 128; i++) fprintf(stderr, "%s%u", i ? "," : "", mask[i]);
            fprintf(stderr, "}; glPolygonStipple(m); }\n");
        }
        glPolygonStipple(mask);
        break;
    }
    case 8: L_Enable(GL_POLYGON_STIPPLE, fz_chance(40)); break;
    case 9: {
        GLdouble eq[4]; GLenum p = GL_CLIP_PLANE0 + (GLenum)fz_int(8);
        eq[0] = fz_f(-1, 1); eq[1] = fz_f(-1, 1); eq[2] = fz_f(-1, 1); eq[3] = fz_f(-0.5f, 0.5f);
        LOG("{ GLdouble eq[4] = {%.17g, %.17g, %.17g, %.17g}; glClipPlane(0x%04X, eq); }", eq[0], eq[1], eq[2], eq[3], p);
        glClipPlane(p, eq);
        break;
    }
    case 10: L_Enable(GL_CLIP_PLANE0 + (GLenum)fz_int(8), fz_chance(40)); break;
    case 11: {
        int x = fz_int(FUZZ_W) - 20, y = fz_int(FUZZ_H) - 20, w = fz_int(FUZZ_W), h = fz_int(FUZZ_H);
        LOG("glScissor(%d, %d, %d, %d);", x, y, w, h); glScissor(x, y, w, h); break;
    }
    case 12: L_Enable(GL_SCISSOR_TEST, fz_chance(40)); break;
    default: {
        int r = fz_chance(80), g = fz_chance(80), b = fz_chance(80), a = fz_chance(80);
        LOG("glColorMask(%d, %d, %d, %d);", r, g, b, a);
        glColorMask((GLboolean)r, (GLboolean)g, (GLboolean)b, (GLboolean)a);
        break;
    }
    }
    if (fz_smooth && fz_chance(10)) L_Enable(fz_int(2) ? GL_POINT_SMOOTH : GL_LINE_SMOOTH, fz_chance(50));
}

int main(int argc, char **argv)
{
    int nops, i;
    fz_smooth = env_int("GLFX_FUZZ_SMOOTH", 0);
    fz_prim_ops = env_int("GLFX_FUZZ_PRIM_OPS", 14);
    nops = fuzz_begin(argc, argv, FUZZ_DEFAULT_SEED);
    for (i = 0; i < nops; i++) {
        int k = fz_int(100);
        if (k < 30) draw_any_prim();
        else if (k < 50) primitive_state_op();
        else fuzz_core_op(fz_int(100));
    }
    return fuzz_end();
}
