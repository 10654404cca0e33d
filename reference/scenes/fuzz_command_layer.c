/* Random legacy program of the GL 2.1 command layer: fuzz_random_state's mix plus vertex arrays, buffer objects, attribute stacks and evaluators (GLFX_FUZZ_SEED). */
/*
 * The generator of fuzz_random_state (fuzz_common.h: matrices, viewport,
 * depth, cull, shading, lighting, material, glBegin/glEnd), with these
 * operations added to its mix:
 *   - vertex arrays: glVertexPointer / glNormalPointer / glColorPointer of
 *     every type GL 2.1 allows them (short, int, float, double positions;
 *     byte, short, int, float, double normals; all eight colour types), packed
 *     or interleaved with a random stride, drawn by glDrawArrays,
 *     glDrawElements (ubyte, ushort, uint indices), glDrawRangeElements,
 *     glMultiDrawArrays, glArrayElement inside glBegin/glEnd, and
 *     glInterleavedArrays (the formats without texture coordinates);
 *   - buffer objects: the same data in an array buffer (glBufferData,
 *     glBufferSubData or a glMapBuffer write), pointers as offsets past a
 *     random lead, indices from an element array buffer;
 *   - glPushClientAttrib / glPopClientAttrib around a second array setup,
 *     then a draw with the restored arrays;
 *   - glPushAttrib / glPopAttrib with random masks, nested up to 4 deep,
 *     around whatever the mix does between them;
 *   - evaluators: glMap2f (vertex 3 or 4, colour, normal maps, orders 2..4),
 *     GL_AUTO_NORMAL, glMapGrid2f + glEvalMesh2(GL_FILL), glEvalCoord2f
 *     inside glBegin/glEnd.
 *   - with GLFX_FUZZ_LISTS=1, display lists: glNewList (GL_COMPILE,
 *     GL_COMPILE_AND_EXECUTE) around a few operations of the mix,
 *     glCallList, glCallLists with a list base. Off by default, so that a
 *     seed's program stays what it was: over seeds 1-120 it agrees with Mesa
 *     on 101 (115 without lists); the seeds that differ only with lists (16
 *     17 27 28 37 47 55 57 58 62 63 81 84 96 106 109, 10 to 40 pixels each)
 *     are not sorted yet.
 *
 * Mesa 22.3.6 defects the generator steers around (MESA_FACTS.md), besides
 * those of fuzz_random_state:
 *   - glPopAttrib(GL_ENABLE_BIT) without GL_LIGHTING_BIT restores no
 *     GL_LIGHTi: every mask with GL_ENABLE_BIT has GL_LIGHTING_BIT too;
 *   - a change made inside an inner glPushAttrib of other groups is forgotten
 *     by the outer glPopAttrib: an inner mask holds the outer one's groups;
 *   - glPopAttrib does not track the colour material again: a glColor follows
 *     every glPopAttrib;
 *   - glPopAttrib does not undo a glMaterial made since the glPushAttrib
 *     (GL_LIGHTING_BIT or GL_ALL_ATTRIB_BITS): while a push with
 *     GL_LIGHTING_BIT is open, glMaterial draws its random numbers but is
 *     not called (found by this scene, seed 34);
 *   - the current colour and normal are undefined after an array draw
 *     (GL 2.1 §2.8) and stale after a map first made them vertex data: a
 *     glColor and a glNormal follow every array and evaluator draw;
 *   - GL_AUTO_NORMAL with an order-1 map reads past the control points:
 *     orders are 2 or more.
 *   - glMultiDrawArrays whose first count is 0 draws nothing at all (the
 *     later counts are dropped too): the first count is never 0 (found by
 *     this scene, seeds 10, 18, 34, 66, 70, 78, 80, 107, 116).
 *
 * Switches: those of fuzz_random_state (GLFX_FUZZ_LOG, GLFX_FUZZ_MAXOPS,
 * GLFX_FUZZ_DRAW_LO/HI, GLFX_FUZZ_NOLIGHT, GLFX_FUZZ_COLOR3F); every array
 * and evaluator draw counts as one primitive for GLFX_FUZZ_DRAW_LO/HI (its
 * set-up calls are still made), and
 *   GLFX_FUZZ_ONLY=mask    only these added operations (1 arrays, 2 client
 *                          attrib, 4 attrib stack, 8 evaluators, 16 lists);
 *                          an operation left out draws no random numbers,
 *                          so what follows it differs from the full run.
 */
#include "fuzz_common.h"
#include <string.h>

#define FUZZ_DEFAULT_SEED 1u

static int fz_only = 0xff;
static GLuint fz_buf[4]; /* array buffers of slots 0, 1; element buffers of slots 0, 1 */

static int draw_next(void)
{
    int emit = fz_draw_wanted(fz_draw_index);
    LOG("/* draw %d%s */", fz_draw_index, emit ? "" : ": not drawn");
    fz_draw_index++;
    return emit;
}

static void after_draw(void)
{
    L_Color();
    L_Normal();
}

/* ---- vertex arrays ------------------------------------------------------- */
#define FZ_MAXV 48
#define FZ_DATA (FZ_MAXV * 96 + 256)

static unsigned char fz_data[2][FZ_DATA];

static const GLenum vtypes[] = { GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE };
static const GLenum ntypes[] = { GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE };
static const GLenum ctypes[] = { GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE };

static int type_size(GLenum t)
{
    switch (t) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_DOUBLE: return 8;
    default: return 4;
    }
}

static const char *type_name(GLenum t)
{
    switch (t) {
    case GL_BYTE: return "GL_BYTE";
    case GL_UNSIGNED_BYTE: return "GL_UNSIGNED_BYTE";
    case GL_SHORT: return "GL_SHORT";
    case GL_UNSIGNED_SHORT: return "GL_UNSIGNED_SHORT";
    case GL_INT: return "GL_INT";
    case GL_UNSIGNED_INT: return "GL_UNSIGNED_INT";
    case GL_FLOAT: return "GL_FLOAT";
    default: return "GL_DOUBLE";
    }
}

/* Stores v as type t; norm: the integer scale (normalized types), else v is
 * already in the type's units. */
static void put(unsigned char *p, GLenum t, double v)
{
    switch (t) {
    case GL_BYTE: { GLbyte x = (GLbyte)v; memcpy(p, &x, 1); break; }
    case GL_UNSIGNED_BYTE: { GLubyte x = (GLubyte)v; memcpy(p, &x, 1); break; }
    case GL_SHORT: { GLshort x = (GLshort)v; memcpy(p, &x, 2); break; }
    case GL_UNSIGNED_SHORT: { GLushort x = (GLushort)v; memcpy(p, &x, 2); break; }
    case GL_INT: { GLint x = (GLint)v; memcpy(p, &x, 4); break; }
    case GL_UNSIGNED_INT: { GLuint x = (GLuint)v; memcpy(p, &x, 4); break; }
    case GL_FLOAT: { GLfloat x = (GLfloat)v; memcpy(p, &x, 4); break; }
    default: memcpy(p, &v, 8); break;
    }
}

static double unorm_max(GLenum t)
{
    switch (t) {
    case GL_BYTE: return 127.0;
    case GL_UNSIGNED_BYTE: return 255.0;
    case GL_SHORT: return 32767.0;
    case GL_UNSIGNED_SHORT: return 65535.0;
    case GL_INT: return 2147483647.0;
    case GL_UNSIGNED_INT: return 4294967295.0;
    default: return 1.0;
    }
}

/* One array set-up: what the pointers are and where the data is. */
typedef struct {
    int nverts;           /* vertices in the data */
    int has_n, has_c;
    int interleaved_format; /* 0, or the glInterleavedArrays format */
    int vbo;
} fz_arrays;

/* A vertex as vertex() in fuzz_common.h makes it, in (x, y, z, w). */
static void rand_position(double *p)
{
    float x = fz_cx + fz_f(-0.6f, 0.6f), y = fz_cy + fz_f(-0.6f, 0.6f), z = fz_cz + fz_f(-0.5f, 0.5f);
    if (fz_chance(8)) {
        int k = fz_int(3);
        if (k == 0) x *= 6; else if (k == 1) y *= 6; else z += fz_f(2.5f, 6);
    }
    p[0] = x; p[1] = y; p[2] = z; p[3] = 1;
    if (fz_chance(10)) {
        double w = fz_f(0.5f, 2);
        p[0] *= w; p[1] *= w; p[2] *= w; p[3] = w;
    }
}

static void bind_buffer(GLenum target, GLuint b)
{
    LOG("glBindBuffer(%s, %u);", target == GL_ARRAY_BUFFER ? "GL_ARRAY_BUFFER" : "GL_ELEMENT_ARRAY_BUFFER", b);
    glBindBuffer(target, b);
}

/* Puts size bytes of data into buffer b bound to target, after a lead of
 * `lead` bytes, in one of three ways. */
static void upload(GLenum target, GLuint b, const void *data, int size, int lead)
{
    const char *tn = target == GL_ARRAY_BUFFER ? "GL_ARRAY_BUFFER" : "GL_ELEMENT_ARRAY_BUFFER";
    int how = fz_int(3);
    bind_buffer(target, b);
    if (how == 0 && lead == 0) {
        LOG("glBufferData(%s, %d, data, GL_STATIC_DRAW);", tn, size);
        glBufferData(target, size, data, GL_STATIC_DRAW);
    } else if (how <= 1) {
        int half = size / 2;
        LOG("glBufferData(%s, %d, NULL, GL_DYNAMIC_DRAW);", tn, lead + size);
        glBufferData(target, lead + size, NULL, GL_DYNAMIC_DRAW);
        LOG("glBufferSubData(%s, %d, %d, data); glBufferSubData(%s, %d, %d, data + %d);", tn, lead, half, tn, lead + half, size - half, half);
        glBufferSubData(target, lead, half, data);
        glBufferSubData(target, lead + half, size - half, (const unsigned char *)data + half);
    } else {
        unsigned char *m;
        LOG("glBufferData(%s, %d, NULL, GL_STREAM_DRAW); memcpy(glMapBuffer(%s, GL_WRITE_ONLY) + %d, data, %d); glUnmapBuffer(%s);", tn, lead + size, tn, lead, size, tn);
        glBufferData(target, lead + size, NULL, GL_STREAM_DRAW);
        m = (unsigned char *)glMapBuffer(target, GL_WRITE_ONLY);
        if (m) {
            memcpy(m + lead, data, (size_t)size);
            glUnmapBuffer(target);
        }
    }
}

/* Fills slot's data with nverts random vertices and sets the pointers (and
 * enables) for them; with `vbo` the data goes into an array buffer. */
static void setup_arrays(int slot, int nverts, fz_arrays *a)
{
    unsigned char *d = fz_data[slot];
    int i, j, lead = 0, size;
    int il = fz_chance(20);
    static const GLenum il_formats[] = { GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F, GL_C4F_N3F_V3F };
    static const char *il_names[] = { "GL_V2F", "GL_V3F", "GL_C4UB_V2F", "GL_C4UB_V3F", "GL_C3F_V3F", "GL_N3F_V3F", "GL_C4F_N3F_V3F" };
    GLenum vt = vtypes[fz_int(4)], nt = ntypes[fz_int(5)], ct = ctypes[fz_int(8)];
    int vs = 2 + fz_int(3), cs = 3 + fz_int(2);
    int voff, noff, coff, vstride, nstride, cstride, separate = fz_chance(35), extra = 4 * fz_int(4);
    double vscale = 1;
    memset(d, 0, FZ_DATA);
    a->nverts = nverts;
    a->has_n = fz_chance(60);
    a->has_c = fz_chance(60);
    a->vbo = fz_chance(40);
    a->interleaved_format = 0;
    if (vt == GL_SHORT || vt == GL_INT) { vs = 4; vscale = vt == GL_SHORT ? 64 : 4096; }
    if (vs == 2 && fz_chance(50)) vs = 3;
    if (il) {
        int f = fz_int(7);
        /* glInterleavedArrays: its own layout, float data, ubyte colours */
        int c = f >= 2 && f != 5, n = f >= 5, v3 = f != 0 && f != 2;
        int cub = f == 2 || f == 3;
        int csz = !c ? 0 : cub ? 4 : f == 4 ? 12 : 16;
        int stride0 = csz + (n ? 12 : 0) + (v3 ? 12 : 8);
        int stride = fz_chance(50) ? 0 : stride0 + extra;
        int st = stride ? stride : stride0;
        a->interleaved_format = (int)il_formats[f];
        a->has_c = c; a->has_n = n;
        for (i = 0; i < nverts; i++) {
            double p[4];
            unsigned char *r = d + i * st;
            int o = 0;
            rand_position(p);
            if (c) {
                float cv[4] = { fz_f(0, 1), fz_f(0, 1), fz_f(0, 1), fz_f(0.2f, 1) };
                if (cub) { for (j = 0; j < 4; j++) put(r + j, GL_UNSIGNED_BYTE, (double)(int)(cv[j] * 255)); o = 4; }
                else { for (j = 0; j < (f == 4 ? 3 : 4); j++) put(r + 4 * j, GL_FLOAT, cv[j]); o = f == 4 ? 12 : 16; }
            }
            if (n) {
                for (j = 0; j < 3; j++) put(r + o + 4 * j, GL_FLOAT, fz_f(-1, 1));
                o += 12;
            }
            for (j = 0; j < (v3 ? 3 : 2); j++) put(r + o + 4 * j, GL_FLOAT, p[j] / p[3]);
        }
        size = nverts * st;
        if (a->vbo) {
            lead = 16 * fz_int(3);
            upload(GL_ARRAY_BUFFER, fz_buf[slot], d, size, lead);
            LOG("glInterleavedArrays(%s, %d, (void *)%d);", il_names[f], stride, lead);
            glInterleavedArrays((GLenum)a->interleaved_format, stride, (const void *)(size_t)lead);
            bind_buffer(GL_ARRAY_BUFFER, 0);
        } else {
            bind_buffer(GL_ARRAY_BUFFER, 0);
            LOG("glInterleavedArrays(%s, %d, data);", il_names[f], stride);
            glInterleavedArrays((GLenum)a->interleaved_format, stride, d);
        }
        return;
    }

    /* the layout: separate packed arrays, or one record per vertex */
    if (separate) {
        vstride = vs * type_size(vt); nstride = 3 * type_size(nt); cstride = cs * type_size(ct);
        voff = 0;
        noff = (voff + nverts * vstride + 7) & ~7;
        coff = (noff + nverts * nstride + 7) & ~7;
        size = coff + nverts * cstride;
    } else {
        int o = 0;
        voff = o; o += vs * type_size(vt); o = (o + 7) & ~7;
        noff = o; o += 3 * type_size(nt); o = (o + 7) & ~7;
        coff = o; o += cs * type_size(ct); o = (o + 7) & ~7;
        vstride = nstride = cstride = o + extra;
        size = nverts * vstride;
    }
    for (i = 0; i < nverts; i++) {
        double p[4];
        rand_position(p);
        if (vs < 4) for (j = 0; j < 3; j++) p[j] /= p[3];
        for (j = 0; j < vs; j++) put(d + voff + i * vstride + j * type_size(vt), vt, vt == GL_SHORT || vt == GL_INT ? (double)(int)(p[j] / p[3] * vscale) : p[j]);
        if (vt == GL_SHORT || vt == GL_INT) put(d + voff + i * vstride + 3 * type_size(vt), vt, vscale);
        {
            float nv[3] = { fz_f(-1, 1), fz_f(-1, 1), fz_f(-0.3f, 1) };
            for (j = 0; j < 3; j++) put(d + noff + i * nstride + j * type_size(nt), nt, nt == GL_FLOAT || nt == GL_DOUBLE ? nv[j] : (double)(long long)(nv[j] * unorm_max(nt)));
        }
        {
            float cv[4] = { fz_f(0, 1), fz_f(0, 1), fz_f(0, 1), fz_f(0.2f, 1) };
            for (j = 0; j < cs; j++) put(d + coff + i * cstride + j * type_size(ct), ct, ct == GL_FLOAT || ct == GL_DOUBLE ? cv[j] : (double)(long long)(cv[j] * unorm_max(ct)));
        }
    }
    if (separate) vstride = nstride = cstride = 0;
    if (a->vbo) {
        lead = 16 * fz_int(3);
        upload(GL_ARRAY_BUFFER, fz_buf[slot], d, size, lead);
    } else {
        bind_buffer(GL_ARRAY_BUFFER, 0);
    }
    {
        /* the pointers: offsets into the buffer, or addresses in data */
        int o = a->vbo ? lead : 0;
        const unsigned char *base = a->vbo ? (const unsigned char *)0 : d;
        const char *bn = a->vbo ? "(char *)0" : "data";
        LOG("glEnableClientState(GL_VERTEX_ARRAY); glVertexPointer(%d, %s, %d, %s + %d);", vs, type_name(vt), vstride, bn, o + voff);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(vs, vt, vstride, base + o + voff);
        if (a->has_n) {
            LOG("glEnableClientState(GL_NORMAL_ARRAY); glNormalPointer(%s, %d, %s + %d);", type_name(nt), nstride, bn, o + noff);
            glEnableClientState(GL_NORMAL_ARRAY);
            glNormalPointer(nt, nstride, base + o + noff);
        } else {
            LOG("glDisableClientState(GL_NORMAL_ARRAY);");
            glDisableClientState(GL_NORMAL_ARRAY);
        }
        if (a->has_c) {
            LOG("glEnableClientState(GL_COLOR_ARRAY); glColorPointer(%d, %s, %d, %s + %d);", cs, type_name(ct), cstride, bn, o + coff);
            glEnableClientState(GL_COLOR_ARRAY);
            glColorPointer(cs, ct, cstride, base + o + coff);
        } else {
            LOG("glDisableClientState(GL_COLOR_ARRAY);");
            glDisableClientState(GL_COLOR_ARRAY);
        }
    }
    if (a->vbo && fz_chance(50)) bind_buffer(GL_ARRAY_BUFFER, 0); /* the pointers keep their buffer */
}

/* A vertex count for mode, as draw_prim chooses them (larger). */
static int prim_count(GLenum mode)
{
    int n = fz_int(16);
    if (mode == GL_TRIANGLES || mode == GL_QUADS) n = fz_int(5) * (mode == GL_TRIANGLES ? 3 : 4) + (fz_chance(20) ? fz_int(3) : 0);
    return n;
}

static const char *prim_name(GLenum m)
{
    static const char *names[] = { "GL_POINTS", "GL_LINES", "GL_LINE_LOOP", "GL_LINE_STRIP", "GL_TRIANGLES", "GL_TRIANGLE_STRIP", "GL_TRIANGLE_FAN", "GL_QUADS", "GL_QUAD_STRIP", "GL_POLYGON" };
    return names[m];
}

/* Sets up slot's arrays and draws them one of six ways.  Returns the
 * glDrawArrays that draws the same vertices again (mode, first, count). */
static void array_draw(int slot, GLenum *rmode, int *rfirst, int *rcount)
{
    GLenum mode = prims[fz_int(6)];
    int n = prim_count(mode), first = fz_chance(40) ? fz_int(6) : 0;
    int nverts = first + n + fz_int(4), how = fz_int(6), emit;
    fz_arrays a;
    if (nverts < 1) nverts = 1;
    if (nverts > FZ_MAXV) nverts = FZ_MAXV;
    fz_cx = fz_f(-1, 1); fz_cy = fz_f(-1, 1); fz_cz = fz_f(-0.8f, 0.8f);
    setup_arrays(slot, nverts, &a);
    *rmode = mode; *rfirst = first; *rcount = n;
    emit = draw_next();
    if (how == 0 || (how == 3 && n < 2)) {
        LOG("glDrawArrays(%s, %d, %d);", prim_name(mode), first, n);
        if (emit) glDrawArrays(mode, first, n);
    } else if (how == 1 || how == 2) {
        /* indices: random vertices of the data */
        static GLuint idx32[64];
        static GLushort idx16[64];
        static GLubyte idx8[64];
        int it = fz_int(3), i, lo = 1 << 30, hi = -1, lead = 0, use_ebo = a.vbo && fz_chance(70);
        GLenum type = it == 0 ? GL_UNSIGNED_BYTE : it == 1 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
        const void *ptr;
        for (i = 0; i < n; i++) {
            int v = fz_chance(70) ? (first + i) % nverts : fz_int(nverts);
            idx32[i] = (GLuint)v; idx16[i] = (GLushort)v; idx8[i] = (GLubyte)v;
            if (v < lo) lo = v;
            if (v > hi) hi = v;
        }
        ptr = it == 0 ? (const void *)idx8 : it == 1 ? (const void *)idx16 : (const void *)idx32;
        if (use_ebo) {
            lead = 4 * fz_int(3);
            upload(GL_ELEMENT_ARRAY_BUFFER, fz_buf[2 + slot], ptr, n * type_size(type == GL_UNSIGNED_INT ? GL_INT : type == GL_UNSIGNED_SHORT ? GL_SHORT : GL_BYTE) + 4, lead);
            ptr = (const char *)0 + lead;
        } else {
            bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        }
        if (fz_log) {
            fprintf(stderr, "/* indices:");
            for (i = 0; i < n; i++) fprintf(stderr, " %u", idx32[i]);
            fprintf(stderr, " */\n");
        }
        if (how == 2 && n > 0) {
            LOG("glDrawRangeElements(%s, %d, %d, %d, %s, %s%d);", prim_name(mode), lo, hi, n, type_name(type), use_ebo ? "(void *)" : "indices + ", lead);
            if (emit) glDrawRangeElements(mode, (GLuint)lo, (GLuint)hi, n, type, ptr);
        } else {
            LOG("glDrawElements(%s, %d, %s, %s%d);", prim_name(mode), n, type_name(type), use_ebo ? "(void *)" : "indices + ", lead);
            if (emit) glDrawElements(mode, n, type, ptr);
        }
    } else if (how == 3) {
        /* glMultiDrawArrays: the vertices cut in up to three draws */
        GLint firsts[3];
        GLsizei counts[3];
        int parts = 2 + fz_int(2), i, at = first;
        for (i = 0; i < parts; i++) {
            int c = i == parts - 1 ? first + n - at : fz_int(first + n - at + 1);
            if (i == 0 && c == 0 && first + n > at) c = 1; /* Mesa defect, see top */
            firsts[i] = at; counts[i] = c; at += c;
            if (fz_chance(20) && at > 0) at--; /* overlapping draws */
        }
        LOG("{ GLint f[3] = {%d, %d, %d}; GLsizei c[3] = {%d, %d, %d}; glMultiDrawArrays(%s, f, c, %d); }", firsts[0], firsts[1], parts > 2 ? firsts[2] : 0, counts[0], counts[1], parts > 2 ? counts[2] : 0, prim_name(mode), parts);
        if (emit) glMultiDrawArrays(mode, firsts, counts, parts);
    } else {
        /* glArrayElement inside glBegin/glEnd */
        int i;
        LOG("glBegin(%s); /* glArrayElement(%d .. %d) */", prim_name(mode), first, first + n - 1);
        if (emit) glBegin(mode);
        for (i = 0; i < n; i++) {
            int v = fz_chance(85) ? (first + i) % nverts : fz_int(nverts);
            LOG("glArrayElement(%d);", v);
            if (emit) glArrayElement(v);
        }
        LOG("glEnd();");
        if (emit) glEnd();
    }
    after_draw();
}

static void arrays_op(void)
{
    GLenum m;
    int f, c;
    array_draw(0, &m, &f, &c);
}

/* glPushClientAttrib, other arrays drawn, glPopClientAttrib, the first ones
 * drawn again with the restored pointers. */
static void client_attrib_op(void)
{
    GLenum m, m2;
    int f, c, f2, c2, emit;
    GLbitfield mask = fz_chance(50) ? GL_CLIENT_VERTEX_ARRAY_BIT : GL_CLIENT_ALL_ATTRIB_BITS;
    array_draw(0, &m, &f, &c);
    LOG("glPushClientAttrib(0x%X);", mask);
    glPushClientAttrib(mask);
    array_draw(1, &m2, &f2, &c2);
    LOG("glPopClientAttrib();");
    glPopClientAttrib();
    emit = draw_next();
    LOG("glDrawArrays(%s, %d, %d);", prim_name(m), f, c);
    if (emit) glDrawArrays(m, f, c);
    after_draw();
}

/* ---- attribute stack --------------------------------------------------- */
static int fz_attrib_depth;
static GLbitfield fz_attrib_mask[4];
static int fz_attrib_mode[4]; /* fz_mode at the push */

static const GLbitfield attrib_bits[] = { GL_CURRENT_BIT, GL_ENABLE_BIT, GL_LIGHTING_BIT, GL_DEPTH_BUFFER_BIT, GL_POLYGON_BIT, GL_TRANSFORM_BIT, GL_VIEWPORT_BIT, GL_EVAL_BIT, GL_COLOR_BUFFER_BIT, GL_HINT_BIT };

static void attrib_op(void)
{
    if (fz_attrib_depth < 4 && (fz_attrib_depth == 0 || fz_chance(50))) {
        GLbitfield mask = 0;
        int i, nbits = 1 + fz_int(3);
        if (fz_chance(15)) mask = GL_ALL_ATTRIB_BITS;
        for (i = 0; i < nbits; i++) mask |= attrib_bits[fz_int(10)];
        if (fz_attrib_depth > 0) mask |= fz_attrib_mask[fz_attrib_depth - 1]; /* Mesa defect, see top */
        if (mask & GL_ENABLE_BIT) mask |= GL_LIGHTING_BIT;                    /* Mesa defect, see top */
        fz_attrib_mask[fz_attrib_depth] = mask;
        fz_attrib_mode[fz_attrib_depth] = fz_mode;
        fz_attrib_depth++;
        if (mask & GL_LIGHTING_BIT) fz_no_material = 1;
        LOG("glPushAttrib(0x%X);", mask);
        glPushAttrib(mask);
    } else if (fz_attrib_depth > 0) {
        fz_attrib_depth--;
        LOG("glPopAttrib();");
        glPopAttrib();
        if (fz_attrib_mask[fz_attrib_depth] & GL_TRANSFORM_BIT) fz_mode = fz_attrib_mode[fz_attrib_depth];
        /* masks nest as supersets: the outer ones hold no more groups */
        fz_no_material = fz_attrib_depth > 0 && (fz_attrib_mask[fz_attrib_depth - 1] & GL_LIGHTING_BIT);
        L_Color(); /* Mesa defect, see top */
    }
}

/* ---- evaluators --------------------------------------------------------- */
static void log_map2(const char *target, float u1, float u2, int ustride, int uorder, float v1, float v2, int vstride, int vorder, const float *pts, int n)
{
    int i;
    if (!fz_log) return;
    fprintf(stderr, "{ static const GLfloat p[%d] = {", n);
    for (i = 0; i < n; i++) fprintf(stderr, "%s%.9g", i ? ", " : "", pts[i]);
    fprintf(stderr, "}; glMap2f(%s, %.9g, %.9g, %d, %d, %.9g, %.9g, %d, %d, p); }\n", target, u1, u2, ustride, uorder, v1, v2, vstride, vorder);
}

static void eval_op(void)
{
    static float vp[4 * 4 * 4], cp[4 * 4 * 4], np[4 * 4 * 3];
    int v4 = fz_chance(25), uo = 2 + fz_int(3), vo = 2 + fz_int(3), i, j, k, emit;
    int dim = v4 ? 4 : 3;
    float u1 = fz_f(-1, 1), u2 = u1 + (fz_chance(20) ? -1 : 1) * fz_f(0.5f, 2);
    float v1 = fz_f(-1, 1), v2 = v1 + (fz_chance(20) ? -1 : 1) * fz_f(0.5f, 2);
    fz_cx = fz_f(-1, 1); fz_cy = fz_f(-1, 1); fz_cz = fz_f(-0.8f, 0.8f);
    for (i = 0; i < uo; i++)
        for (j = 0; j < vo; j++) {
            float *p = vp + (i * vo + j) * dim;
            float w = v4 ? fz_f(0.5f, 2) : 1;
            p[0] = (fz_cx - 0.6f + 1.2f * (float)i / (float)(uo - 1) + fz_f(-0.2f, 0.2f)) * w;
            p[1] = (fz_cy - 0.6f + 1.2f * (float)j / (float)(vo - 1) + fz_f(-0.2f, 0.2f)) * w;
            p[2] = (fz_cz + fz_f(-0.5f, 0.5f)) * w;
            if (v4) p[3] = w;
            for (k = 0; k < 4; k++) cp[(i * vo + j) * 4 + k] = k == 3 ? fz_f(0.3f, 1) : fz_f(0, 1);
            for (k = 0; k < 3; k++) np[(i * vo + j) * 3 + k] = k == 2 ? fz_f(-0.3f, 1) : fz_f(-1, 1);
        }
    log_map2(v4 ? "GL_MAP2_VERTEX_4" : "GL_MAP2_VERTEX_3", u1, u2, vo * dim, uo, v1, v2, dim, vo, vp, uo * vo * dim);
    glMap2f(v4 ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3, u1, u2, vo * dim, uo, v1, v2, dim, vo, vp);
    L_Enable(v4 ? GL_MAP2_VERTEX_4 : GL_MAP2_VERTEX_3, 1);
    L_Enable(v4 ? GL_MAP2_VERTEX_3 : GL_MAP2_VERTEX_4, 0);
    if (fz_chance(50)) {
        log_map2("GL_MAP2_COLOR_4", u1, u2, vo * 4, uo, v1, v2, 4, vo, cp, uo * vo * 4);
        glMap2f(GL_MAP2_COLOR_4, u1, u2, vo * 4, uo, v1, v2, 4, vo, cp);
        L_Enable(GL_MAP2_COLOR_4, 1);
    } else {
        L_Enable(GL_MAP2_COLOR_4, 0);
    }
    if (fz_chance(40)) {
        log_map2("GL_MAP2_NORMAL", u1, u2, vo * 3, uo, v1, v2, 3, vo, np, uo * vo * 3);
        glMap2f(GL_MAP2_NORMAL, u1, u2, vo * 3, uo, v1, v2, 3, vo, np);
        L_Enable(GL_MAP2_NORMAL, 1);
    } else {
        L_Enable(GL_MAP2_NORMAL, 0);
    }
    L_Enable(GL_AUTO_NORMAL, fz_chance(40));
    emit = draw_next();
    if (fz_chance(60)) {
        int nu = 1 + fz_int(6), nv = 1 + fz_int(6);
        int i1 = fz_int(nu + 1), i2 = i1 + fz_int(nu + 1 - i1), j1 = fz_int(nv + 1), j2 = j1 + fz_int(nv + 1 - j1);
        LOG("glMapGrid2f(%d, %.9g, %.9g, %d, %.9g, %.9g);", nu, u1, u2, nv, v1, v2);
        glMapGrid2f(nu, u1, u2, nv, v1, v2);
        LOG("glEvalMesh2(GL_FILL, %d, %d, %d, %d);", i1, i2, j1, j2);
        if (emit) glEvalMesh2(GL_FILL, i1, i2, j1, j2);
    } else {
        GLenum mode = prims[fz_int(6)];
        int n = prim_count(mode);
        LOG("glBegin(%s);", prim_name(mode));
        if (emit) glBegin(mode);
        for (i = 0; i < n; i++) {
            float u = u1 + (u2 - u1) * fz_f(0, 1), v = v1 + (v2 - v1) * fz_f(0, 1);
            LOG("glEvalCoord2f(%.9g, %.9g);", u, v);
            if (emit) glEvalCoord2f(u, v);
        }
        LOG("glEnd();");
        if (emit) glEnd();
    }
    after_draw();
}

/* ---- display lists ---------------------------------------------------------
 * GLFX_FUZZ_LISTS=1: glNewList (GL_COMPILE, GL_COMPILE_AND_EXECUTE) around a few
 * operations of the mix, glCallList, glCallLists. */
static int fz_lists;  /* GLFX_FUZZ_LISTS */
static GLuint fz_list_base;
static int fz_list_made[8];

static void lists_op(void)
{
    int k = fz_int(3);
    if (k == 0 || !fz_list_made[0]) {
        int l = fz_int(8), ops = 1 + fz_int(4), i;
        GLenum mode = fz_chance(50) ? GL_COMPILE : GL_COMPILE_AND_EXECUTE;
        LOG("glNewList(%u, %s);", fz_list_base + l, mode == GL_COMPILE ? "GL_COMPILE" : "GL_COMPILE_AND_EXECUTE");
        glNewList(fz_list_base + (GLuint)l, mode);
        for (i = 0; i < ops; i++) {
            int o = fz_int(100);
            /* what a list may hold: no client-side array state, no push depth */
            if (o < 50) draw_prim();
            else if (o < 65) state_op();
            else if (o < 75) L_Light();
            else if (o < 85) L_Material(0);
            else { float x = fz_f(-0.3f, 0.3f), y = fz_f(-0.3f, 0.3f); LOG("glTranslatef(%.9g, %.9g, 0);", x, y); glTranslatef(x, y, 0); }
        }
        LOG("glEndList();");
        glEndList();
        fz_list_made[l] = 1;
        if (l != 0) fz_list_made[0] = 1;
    } else if (k == 1) {
        GLuint l = fz_list_base + (GLuint)fz_int(8);
        LOG("glCallList(%u);", l);
        glCallList(l);
    } else {
        GLubyte ids[4];
        int n = 1 + fz_int(4), i;
        for (i = 0; i < n; i++) ids[i] = (GLubyte)fz_int(8);
        LOG("glListBase(%u); { GLubyte ids[4] = {%u, %u, %u, %u}; glCallLists(%d, GL_UNSIGNED_BYTE, ids); } glListBase(0);", fz_list_base, ids[0], ids[1], ids[2], ids[3], n);
        glListBase(fz_list_base);
        glCallLists(n, GL_UNSIGNED_BYTE, ids);
        glListBase(0);
    }
}

int main(int argc, char **argv)
{
    int nops, i;
    fz_only = env_int("GLFX_FUZZ_ONLY", 0xff);
    nops = fuzz_begin(argc, argv, FUZZ_DEFAULT_SEED);
    glGenBuffers(4, fz_buf);
    fz_lists = env_int("GLFX_FUZZ_LISTS", 0);
    if (fz_lists) fz_list_base = glGenLists(8);
    for (i = 0; i < nops; i++) {
        int k = fz_int(140);
        if (k < 100) fuzz_core_op(k);
        else if (k < 115) { if (fz_only & 1) arrays_op(); }
        else if (k < 120) { if (fz_only & 2) client_attrib_op(); }
        else if (k < 128) { if (fz_only & 4) attrib_op(); }
        else if (k < 135) { if (fz_only & 8) eval_op(); }
        else {
            if (fz_lists && (fz_only & 16)) lists_op();
        }
    }
    return fuzz_end();
}
