/* scene.c - helper library for the reference scenes (see scene.h). */
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GUARD_BYTES 256
#define CANARY 0xA5

static struct {
    OSMesaContext ctx;
    unsigned char *buffer;     /* client colour buffer (plus guard zone) */
    size_t buffer_bytes;       /* image part: row_pixels * height * bpp */
    int width, height;
    int row_pixels;            /* pixels per row in the client buffer */
    int bpp;                   /* bytes per pixel of the client buffer */
    GLenum format;             /* format the scene asked for */
    GLenum type;               /* buffer type: GL_UNSIGNED_BYTE (default), GL_UNSIGNED_SHORT, GL_FLOAT,
                                  GL_UNSIGNED_SHORT_5_6_5 */
    GLenum ctx_format;         /* format given to OSMesa (differs: RGB emulation) */
    int rgb_via_rgba;          /* Mesa side of an RGB/BGR scene: rendered as RGBA (scene.c) */
    int y_up;                  /* orientation used to decode the buffer */
    int has_depth;
    unsigned int cleared_depth;
    const char *prefix;
    const char *refused;       /* non-NULL: scene_begin_try was refused */
} S;

static void fail(const char *what)
{
    fprintf(stderr, "scene: %s\n", what);
    exit(2);
}

static int format_has_alpha(GLenum format)
{
    return format == OSMESA_RGBA || format == OSMESA_BGRA || format == OSMESA_ARGB;
}

static int format_bpp(GLenum format)
{
    switch (format) {
    case OSMESA_RGBA: case OSMESA_BGRA: case OSMESA_ARGB: return 4;
    case OSMESA_RGB: case OSMESA_BGR: return 3;
    case OSMESA_RGB_565: return 2;
    default: return 0;
    }
}

/* Bytes a pixel of (format, type): Mesa's 16-bit and float buffers have 4
 * channels (3 for OSMESA_RGB) of 2 or 4 bytes. */
static int buffer_bpp(GLenum format, GLenum type)
{
    int channels = format == OSMESA_RGB || format == OSMESA_BGR ? 3 : 4;
    switch (type) {
    case GL_UNSIGNED_SHORT: return channels * 2;
    case GL_FLOAT: return channels * 4;
    case GL_UNSIGNED_SHORT_5_6_5: return 2;
    default: return format_bpp(format);
    }
}

/* The dump's sample kind (header field 10): "8" (bytes), "16" (16-bit unorm
 * channels), "32f" (float channels), "565" (the 5-6-5 word's own channel
 * values, 0..31 / 0..63, one byte each). glfx_compare counts differences in
 * units of the kind's least significant bit (floats: units in the last place). */
static const char *sample_kind(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_SHORT: return "16";
    case GL_FLOAT: return "32f";
    case GL_UNSIGNED_SHORT_5_6_5: return "565";
    default: return "8";
    }
}
static int sample_bytes(GLenum type) { return type == GL_UNSIGNED_SHORT ? 2 : type == GL_FLOAT ? 4 : 1; }

static GLenum g_buffer_type = GL_UNSIGNED_BYTE;
void scene_set_buffer_type(GLenum type) { g_buffer_type = type; }

/* One pixel of a 16-bit, float or 5-6-5 buffer as four samples of
 * sample_bytes(type) (R, G, B, A: Mesa stores these types as RGBA whatever
 * the OSMesa format; missing alpha as 1.0). */
static void decode_wide_pixel(const unsigned char *p, unsigned char *out)
{
    int has_alpha = format_has_alpha(S.format), k;
    if (S.type == GL_UNSIGNED_SHORT_5_6_5) {
        unsigned short w;
        memcpy(&w, p, 2);
        out[0] = (unsigned char)(w >> 11); out[1] = (unsigned char)((w >> 5) & 63);
        out[2] = (unsigned char)(w & 31); out[3] = 255;
    } else if (S.type == GL_UNSIGNED_SHORT) {
        unsigned short v[4] = {0, 0, 0, 65535};
        memcpy(v, p, has_alpha ? 8 : 6);
        memcpy(out, v, 8);
    } else {
        float v[4] = {0, 0, 0, 1.0f};
        memcpy(v, p, has_alpha ? 16 : 12);
        memcpy(out, v, 16);
    }
    (void)k;
}


/* Decode one client-buffer pixel into RGBA. */
static void decode_pixel(const unsigned char *p, unsigned char out[4])
{
    switch (S.ctx_format) {
    case OSMESA_RGBA: out[0] = p[0]; out[1] = p[1]; out[2] = p[2]; out[3] = p[3]; break;
    case OSMESA_BGRA: out[0] = p[2]; out[1] = p[1]; out[2] = p[0]; out[3] = p[3]; break;
    case OSMESA_ARGB: out[0] = p[1]; out[1] = p[2]; out[2] = p[3]; out[3] = p[0]; break;
    case OSMESA_RGB:  out[0] = p[0]; out[1] = p[1]; out[2] = p[2]; out[3] = 255; break;
    case OSMESA_BGR:  out[0] = p[2]; out[1] = p[1]; out[2] = p[0]; out[3] = 255; break;
    }
    if (!format_has_alpha(S.format)) out[3] = 255;
}

static unsigned int read_depth_value(const unsigned char *p, int bytes)
{
    unsigned int v = 0;
    if (bytes == 2) { unsigned short s; memcpy(&s, p, 2); v = s; }
    else if (bytes == 4) { memcpy(&v, p, 4); }
    else if (bytes == 1) { v = *p; }
    return v;
}

static int stencil_bits;

void scene_set_stencil_bits(int bits) { stencil_bits = bits; }

int scene_width(void) { return S.width; }
int scene_height(void) { return S.height; }

static int g_accum_bits;
void scene_set_accum_bits(int bits) { g_accum_bits = bits; }

void scene_begin(int argc, char **argv, int width, int height)
{
    scene_options o;
    memset(&o, 0, sizeof o);
    o.width = width;
    o.height = height;
    o.format = OSMESA_RGBA;
    o.depth_bits = 24;
    o.y_up = 1;
    o.row_length = 0;
    scene_begin_ext(argc, argv, &o);
}

void scene_begin_ext(int argc, char **argv, const scene_options *opts)
{
    if (scene_begin_try(argc, argv, opts) != 0) {
        fprintf(stderr, "scene: OSMesa refused the context (%s)\n", S.refused);
        exit(2);
    }
}

int scene_begin_try(int argc, char **argv, const scene_options *opts)
{
    GLint dw = 0, dh = 0, dbytes = 0;
    void *dbuf = NULL;
    int depth_bits;

    if (argc < 2 || !argv[1][0]) {
        fprintf(stderr, "usage: %s OUTPUT_PREFIX\n", argc > 0 ? argv[0] : "scene");
        exit(2);
    }
    memset(&S, 0, sizeof S);
    S.prefix = argv[1];
    S.width = opts->width;
    S.height = opts->height;
    S.format = opts->format ? opts->format : OSMESA_RGBA;
    if (!format_bpp(S.format)) fail("unsupported OSMesa format");
    S.ctx_format = S.format;
    S.type = g_buffer_type;
    if (S.type == GL_UNSIGNED_BYTE) {
        /* Mesa 22.3 llvmpipe corrupts OSMESA_RGB renderings and refuses
         * OSMESA_BGR at OSMesaMakeCurrent; on the Mesa side render RGBA and
         * present it in the 3-byte layout (GLFX_RGB_RAW=1 disables this). */
        const char *side = getenv("GLFX_SIDE"), *raw = getenv("GLFX_RGB_RAW");
        if ((S.format == OSMESA_RGB || S.format == OSMESA_BGR) && side && strcmp(side, "mesa") == 0 &&
            !(raw && raw[0] && strcmp(raw, "0") != 0)) {
            S.rgb_via_rgba = 1;
            S.ctx_format = OSMESA_RGBA;
        }
    }
    S.bpp = buffer_bpp(S.ctx_format, S.type);
    if (S.width <= 0 || S.height <= 0) fail("bad buffer size");
    S.row_pixels = opts->row_length > 0 ? opts->row_length : S.width;
    if (S.row_pixels < S.width) fail("row_length smaller than width");
    S.y_up = opts->y_up == 0 ? 0 : 1;   /* -1: Mesa's default, which is 1 */
    depth_bits = opts->depth_bits < 0 ? 24 : opts->depth_bits;

    S.buffer_bytes = (size_t)S.row_pixels * S.height * S.bpp;
    S.buffer = (unsigned char *)malloc(S.buffer_bytes + GUARD_BYTES);
    if (!S.buffer) fail("out of memory");
    memset(S.buffer, CANARY, S.buffer_bytes + GUARD_BYTES);

    S.ctx = OSMesaCreateContextExt(S.ctx_format, depth_bits, stencil_bits, g_accum_bits, NULL);
    if (!S.ctx) {
        S.refused = "create";
        return -1;
    }
    if (!OSMesaMakeCurrent(S.ctx, S.buffer, S.type, S.width, S.height)) {
        S.refused = "makecurrent";
        return -1;
    }
    if (opts->row_length > 0)
        OSMesaPixelStore(OSMESA_ROW_LENGTH, opts->row_length);
    if (opts->y_up >= 0)
        OSMesaPixelStore(OSMESA_Y_UP, opts->y_up ? 1 : 0);

    glViewport(0, 0, S.width, S.height);
    scene_clear();

    /* Remember what a cleared depth value looks like (for coverage). */
    glFinish();
    if (OSMesaGetDepthBuffer(S.ctx, &dw, &dh, &dbytes, &dbuf) && dbuf && dbytes > 0) {
        S.has_depth = 1;
        S.cleared_depth = read_depth_value((const unsigned char *)dbuf, dbytes);
    }
    return 0;
}

void scene_clear(void)
{
    glClearColor(SCENE_KEY_R / 255.0f, SCENE_KEY_G / 255.0f, SCENE_KEY_B / 255.0f,
                 SCENE_KEY_A / 255.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void scene_ortho_pixels(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)S.width, 0.0, (double)S.height, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static unsigned int lcg_state = 12345u;

void scene_srand(unsigned int seed) { lcg_state = seed; }

unsigned scene_rand(void)
{
    lcg_state = lcg_state * 1103515245u + 12345u;
    return (lcg_state >> 1) & 0x7fffffffu;
}

float scene_randf(float lo, float hi)
{
    /* 24 random bits -> exactly representable fraction in [0,1) */
    float f = (float)(scene_rand() >> 7) / 16777216.0f;
    return lo + (hi - lo) * f;
}

static void write_info_line(FILE *f, int readpixels)
{
    static const struct { GLenum e; const char *n; } gl_ints[] = {
        { GL_RED_BITS, "red_bits" }, { GL_GREEN_BITS, "green_bits" },
        { GL_BLUE_BITS, "blue_bits" }, { GL_ALPHA_BITS, "alpha_bits" },
        { GL_DEPTH_BITS, "depth_bits" }, { GL_STENCIL_BITS, "stencil_bits" }, { GL_ACCUM_RED_BITS, "accum_bits" },
    };
    static const struct { GLint e; const char *n; } os_ints[] = {
        { OSMESA_WIDTH, "osmesa_width" }, { OSMESA_HEIGHT, "osmesa_height" },
        { OSMESA_FORMAT, "osmesa_format" }, { OSMESA_TYPE, "osmesa_type" },
        { OSMESA_ROW_LENGTH, "osmesa_row_length" }, { OSMESA_Y_UP, "osmesa_y_up" },
    };
    size_t i;
    fprintf(f, "info");
    if (S.refused) {
        fprintf(f, " refused=%s", S.refused);
    } else if (readpixels) {
        fprintf(f, " readpixels=1");
    } else {
        GLenum err = glGetError();   /* first pending GL error of the scene */
        fprintf(f, " gl_error=0x%04x", (unsigned)err);
        if (S.rgb_via_rgba) fprintf(f, " mesa_rgb_via_rgba=1");
        for (i = 0; i < sizeof gl_ints / sizeof gl_ints[0]; i++) {
            GLint v = -1;
            glGetIntegerv(gl_ints[i].e, &v);
            if (S.rgb_via_rgba && gl_ints[i].e == GL_ALPHA_BITS) v = 0;
            fprintf(f, " %s=%d", gl_ints[i].n, (int)v);
        }
        for (i = 0; i < sizeof os_ints / sizeof os_ints[0]; i++) {
            GLint v = -1;
            OSMesaGetIntegerv(os_ints[i].e, &v);
            if (S.rgb_via_rgba && os_ints[i].e == OSMESA_FORMAT) v = (GLint)S.format;
            fprintf(f, " %s=%d", os_ints[i].n, (int)v);
        }
    }
    fprintf(f, "\n");
}

static FILE *open_output(const char *suffix)
{
    size_t n = strlen(S.prefix) + strlen(suffix) + 1;
    char *path = (char *)malloc(n);
    FILE *f;
    if (!path) fail("out of memory");
    snprintf(path, n, "%s%s", S.prefix, suffix);
    f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "scene: cannot write %s\n", path);
        exit(2);
    }
    free(path);
    return f;
}

static void close_output(FILE *f)
{
    if (ferror(f) || fclose(f) != 0) fail("write error");
}

void scene_readpixels_check(void)
{
    /* 16-bit and float buffers are read in their own type. */
    GLenum rtype = S.type == GL_UNSIGNED_SHORT || S.type == GL_FLOAT ? S.type : GL_UNSIGNED_BYTE;
    int sbytes = sample_bytes(rtype);
    size_t row = (size_t)S.width * 4 * sbytes;
    unsigned char *px = (unsigned char *)malloc(row * S.height);
    FILE *f;
    size_t i;
    int y;
    if (S.refused) { free(px); return; }
    if (!px) fail("out of memory");
    memset(px, 0, row * S.height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, S.width, S.height, GL_RGBA, rtype, px);
    f = open_output(".readpixels");
    fprintf(f, "GLFX1 %d %d %d %d %d %d %u %d %s\n", S.width, S.height,
            format_has_alpha(S.format) ? 4 : 3, 0, 0, 0, 0u, 0, sample_kind(rtype));
    write_info_line(f, 1);
    if (S.rgb_via_rgba)                          /* an RGB buffer reads alpha 1.0 */
        for (i = 0; i < (size_t)S.width * S.height; i++) px[i * 4 + 3] = 255;
    for (y = S.height - 1; y >= 0; y--)          /* GL rows are bottom-up */
        fwrite(px + (size_t)y * row, 1, row, f);
    close_output(f);
    free(px);
}

/* scene_end after a refused scene_begin_try: an all-KEY image. */
static int end_refused(void)
{
    static const unsigned char key[4] = {SCENE_KEY_R, SCENE_KEY_G, SCENE_KEY_B, SCENE_KEY_A};
    FILE *f = open_output(".glfx");
    int i, k;
    fprintf(f, "GLFX1 %d %d %d %d %d %d %u %d %s\n", S.width, S.height,
            format_has_alpha(S.format) ? 4 : 3, 0, 0, 0, 0u, 0, sample_kind(S.type));
    write_info_line(f, 0);
    for (i = 0; i < S.width * S.height; i++) {
        /* The KEY as each kind stores a clear to it (glfx_compare's key). */
        for (k = 0; k < 4; k++) {
            int a = k == 3 && !format_has_alpha(S.format);
            float v = a ? 1.0f : key[k] / 255.0f;
            if (S.type == GL_UNSIGNED_SHORT) {
                unsigned short u = (unsigned short)(a ? 65535 : key[k] * 257);
                fwrite(&u, 2, 1, f);
            } else if (S.type == GL_FLOAT) {
                fwrite(&v, 4, 1, f);
            } else if (S.type == GL_UNSIGNED_SHORT_5_6_5) {
                static const unsigned char key565[4] = {0, 1, 1, 255};
                fwrite(&key565[k], 1, 1, f);
            } else {
                unsigned char b = a ? 255 : key[k];
                fwrite(&b, 1, 1, f);
            }
        }
    }
    close_output(f);
    if (S.ctx) OSMesaDestroyContext(S.ctx);
    free(S.buffer);
    memset(&S, 0, sizeof S);
    g_buffer_type = GL_UNSIGNED_BYTE;
    return 0;
}

int scene_end(void)
{
    GLint dw = 0, dh = 0, dbytes = 0;
    void *dbuf = NULL;
    int guard_damage = 0;
    size_t i, row_bytes = (size_t)S.row_pixels * S.bpp;
    unsigned char *rgba;
    FILE *f;
    int x, y;

    if (S.refused)
        return end_refused();

    glFinish();

    /* Bytes outside the image area must be untouched. */
    for (y = 0; y < S.height; y++)
        for (i = (size_t)S.width * S.bpp; i < row_bytes; i++)
            guard_damage += S.buffer[(size_t)y * row_bytes + i] != CANARY;
    for (i = 0; i < GUARD_BYTES; i++)
        guard_damage += S.buffer[S.buffer_bytes + i] != CANARY;

    if (!(S.has_depth && OSMesaGetDepthBuffer(S.ctx, &dw, &dh, &dbytes, &dbuf) && dbuf &&
          dbytes > 0)) {
        dw = dh = dbytes = 0;
        dbuf = NULL;
    }

    f = open_output(".glfx");
    fprintf(f, "GLFX1 %d %d %d %d %d %d %u %d %s\n", S.width, S.height,
            format_has_alpha(S.format) ? 4 : 3, (int)dw, (int)dh, (int)dbytes,
            S.cleared_depth, guard_damage, sample_kind(S.type));
    write_info_line(f, 0);

    {
        size_t px_bytes = 4 * (size_t)(S.type == GL_UNSIGNED_BYTE ? 1 : sample_bytes(S.type));
        rgba = (unsigned char *)malloc((size_t)S.width * px_bytes);
        if (!rgba) fail("out of memory");
        for (y = 0; y < S.height; y++) {             /* output row 0 = top */
            int src_row = S.y_up ? S.height - 1 - y : y;
            const unsigned char *src = S.buffer + (size_t)src_row * row_bytes;
            for (x = 0; x < S.width; x++) {
                if (S.type == GL_UNSIGNED_BYTE)
                    decode_pixel(src + (size_t)x * S.bpp, rgba + (size_t)x * 4);
                else
                    decode_wide_pixel(src + (size_t)x * S.bpp, rgba + (size_t)x * px_bytes);
            }
            fwrite(rgba, 1, (size_t)S.width * px_bytes, f);
        }
    }
    free(rgba);

    /* Mesa's depth buffer memory is bottom row first; write top row first. */
    for (y = dh - 1; y >= 0; y--)
        fwrite((const unsigned char *)dbuf + (size_t)y * dw * dbytes, 1,
               (size_t)dw * dbytes, f);
    close_output(f);

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(S.ctx);
    free(S.buffer);
    memset(&S, 0, sizeof S);
    g_buffer_type = GL_UNSIGNED_BYTE;
    return 0;
}
