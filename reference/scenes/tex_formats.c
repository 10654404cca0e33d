/* Every internal format and every unpack format / type, uploaded with
 * glTexImage2D and drawn as a grid of small quads (GL_NEAREST, GL_REPLACE,
 * one 5x4-texel image per cell at 4 pixels a texel; non power of two on
 * purpose). The same logical image is encoded in C for each upload, so the
 * cells differ only by what the format keeps:
 *   - every sized and unsized internal format of GL 2.1 (1, 2, 3, 4 and the
 *     sRGB ones included; not the generic compressed ones, which Mesa may
 *     really compress), from GL_RGBA / GL_UNSIGNED_BYTE;
 *   - every unpack format and type into GL_RGBA8 (signed, wide and float
 *     types, every packed type in both orders, BGR / BGRA);
 *   - the unsized GL_RGB / GL_RGBA from packed and float data (Mesa may
 *     choose its storage from the data's type);
 *   - glPixelStore unpack state: alignment 1, 2 and 8, row length with
 *     skip pixels and skip rows, swap bytes (never with skips: Mesa 22.3.6
 *     gets that wrong, see MESA_FACTS.md);
 *   - two uploads from a pixel unpack buffer object (glTexImage2D and
 *     glTexSubImage2D at an offset into the buffer). */
#include "tex_common.h"

#define W 5
#define H 4

/* The logical image: values chosen to land between the steps of every
 * channel width (so each format's rounding shows), alpha varying. */
static float texel(int x, int y, int c)
{
    switch (c) {
    case 0: return (x + W * y) / (float)(W * H - 1);
    case 1: return 1.0f - x * 0.23f;
    case 2: return 0.1f + y * 0.29f;
    default: return 0.2f + 0.2f * ((x + 2 * y) % 5);
    }
}

/* Channels (0 = R, 1 = G, 2 = B, 3 = A) of each client format, in memory
 * order; luminance takes the red value. */
static int channels(GLenum format, int idx[4])
{
    switch (format) {
    case GL_RED: case GL_LUMINANCE: idx[0] = 0; return 1;
    case GL_GREEN: idx[0] = 1; return 1;
    case GL_BLUE: idx[0] = 2; return 1;
    case GL_ALPHA: idx[0] = 3; return 1;
    case GL_LUMINANCE_ALPHA: idx[0] = 0; idx[1] = 3; return 2;
    case GL_RGB: idx[0] = 0; idx[1] = 1; idx[2] = 2; return 3;
    case GL_BGR: idx[0] = 2; idx[1] = 1; idx[2] = 0; return 3;
    case GL_RGBA: idx[0] = 0; idx[1] = 1; idx[2] = 2; idx[3] = 3; return 4;
    case GL_BGRA: idx[0] = 2; idx[1] = 1; idx[2] = 0; idx[3] = 3; return 4;
    }
    return 0;
}

/* Bit widths of a packed type, most significant field first, and whether
 * it is a _REV type (its first component in the least significant bits).
 * Returns the group size in bytes, 0 for a type that is not packed. */
static int packed(GLenum type, int widths[4], int *n, int *rev)
{
    static const struct { GLenum t; int bytes, n, rev, w[4]; } tab[] = {
        { GL_UNSIGNED_BYTE_3_3_2, 1, 3, 0, { 3, 3, 2 } },
        { GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3, 1, { 2, 3, 3 } },
        { GL_UNSIGNED_SHORT_5_6_5, 2, 3, 0, { 5, 6, 5 } },
        { GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3, 1, { 5, 6, 5 } },
        { GL_UNSIGNED_SHORT_4_4_4_4, 2, 4, 0, { 4, 4, 4, 4 } },
        { GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, 1, { 4, 4, 4, 4 } },
        { GL_UNSIGNED_SHORT_5_5_5_1, 2, 4, 0, { 5, 5, 5, 1 } },
        { GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, 1, { 1, 5, 5, 5 } },
        { GL_UNSIGNED_INT_8_8_8_8, 4, 4, 0, { 8, 8, 8, 8 } },
        { GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4, 1, { 8, 8, 8, 8 } },
        { GL_UNSIGNED_INT_10_10_10_2, 4, 4, 0, { 10, 10, 10, 2 } },
        { GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, 1, { 2, 10, 10, 10 } },
    };
    unsigned i;
    for (i = 0; i < sizeof tab / sizeof tab[0]; i++)
        if (tab[i].t == type) {
            memcpy(widths, tab[i].w, sizeof tab[i].w);
            *n = tab[i].n;
            *rev = tab[i].rev;
            return tab[i].bytes;
        }
    return 0;
}

static int type_size(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    default: return 4;
    }
}

/* Stores one element (native byte order, then swapped when asked). */
static void put(unsigned char *p, unsigned long long v, int size, int swap)
{
    int i;
    union { unsigned char b[4]; unsigned short s; unsigned int u; } e;
    if (size == 1) e.b[0] = (unsigned char)v;
    else if (size == 2) e.s = (unsigned short)v;
    else e.u = (unsigned int)v;
    for (i = 0; i < size; i++)
        p[i] = e.b[swap ? size - 1 - i : i];
}

static unsigned long long scaled(float f, double max) { return (unsigned long long)(f * max + 0.5); }

typedef struct {
    int alignment, row_length, skip_pixels, skip_rows, swap;
} unpack;

/* Encodes the logical image as format/type under the unpack state `u` and
 * sets that state; bytes the unpack state skips hold 0xa5. Returns the
 * bytes (4096 of them, the image from the start). */
static const unsigned char *encode(GLenum format, GLenum type, const unpack *u)
{
    static unsigned char mem[4096];
    int idx[4], widths[4], pn = 0, rev = 0, x, y, c;
    int comps = channels(format, idx);
    int group = packed(type, widths, &pn, &rev);
    int elem = group ? group : type_size(type), per_pixel = group ? 1 : comps;
    int row_px = u->row_length ? u->row_length : W;
    int a = u->alignment, row_bytes = row_px * per_pixel * elem;
    int stride = elem >= a ? row_bytes : (row_bytes + a - 1) / a * a;
    memset(mem, 0xa5, sizeof mem);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            unsigned char *p = mem + (y + u->skip_rows) * stride + (x + u->skip_pixels) * per_pixel * elem;
            if (group) {
                unsigned long long v = 0;
                int shift = 0, i;
                for (i = 0; i < pn; i++) {
                    int w = rev ? widths[pn - 1 - i] : widths[i];
                    int s = rev ? shift : 0;
                    if (!rev) {
                        int k, below = 0;
                        for (k = i + 1; k < pn; k++) below += widths[k];
                        s = below;
                    }
                    v |= scaled(texel(x, y, idx[i]), (double)((1u << w) - 1)) << s;
                    shift += w;
                }
                put(p, v, group, u->swap);
                continue;
            }
            for (c = 0; c < comps; c++) {
                float f = texel(x, y, idx[c]);
                unsigned char *q = p + c * elem;
                switch (type) {
                case GL_UNSIGNED_BYTE: put(q, scaled(f, 255.0), 1, 0); break;
                case GL_BYTE: put(q, scaled(f, 127.0), 1, 0); break;
                case GL_UNSIGNED_SHORT: put(q, scaled(f, 65535.0), 2, u->swap); break;
                case GL_SHORT: put(q, scaled(f, 32767.0), 2, u->swap); break;
                case GL_UNSIGNED_INT: put(q, scaled(f, 4294967295.0), 4, u->swap); break;
                case GL_INT: put(q, scaled(f, 2147483647.0), 4, u->swap); break;
                case GL_FLOAT: {
                    union { float f; unsigned int u; } fu;
                    fu.f = f;
                    put(q, fu.u, 4, u->swap);
                    break;
                }
                }
            }
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, u->alignment);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, u->row_length);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, u->skip_pixels);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, u->skip_rows);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, u->swap);
    return mem;
}

/* Encodes and uploads as `internal`, from client memory. */
static void upload(GLenum internal, GLenum format, GLenum type, const unpack *u)
{
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, W, H, 0, format, type, encode(format, type, u));
}

/* The same through a pixel unpack buffer object: the data at byte 64 of
 * the buffer; `sub`: an empty glTexImage2D, then glTexSubImage2D from the
 * buffer. */
static void upload_pbo(GLenum internal, GLenum format, GLenum type, const unpack *u, int sub)
{
    static unsigned char data[64 + 4096];
    GLuint buffer;
    memset(data, 0x5a, 64);
    memcpy(data + 64, encode(format, type, u), 4096);
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof data, data, GL_STATIC_DRAW);
    if (sub) {
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, W, H, 0, format, type, NULL);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, W, H, format, type, (const void *)(size_t)64);
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, W, H, 0, format, type, (const void *)(size_t)64);
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glDeleteBuffers(1, &buffer);
}

typedef struct {
    GLenum internal, format, type;
    unpack u;
} upload_case;

#define PLAIN { 4, 0, 0, 0, 0 }

static const upload_case cases[] = {
    /* internal formats, from GL_RGBA / GL_UNSIGNED_BYTE */
    { GL_RGB8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGB5_A1, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_R3_G3_B2, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA16, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGB4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGB5, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGB10, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGB12, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGB16, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA2, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA12, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_LUMINANCE4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE12, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_LUMINANCE16, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_ALPHA4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_ALPHA12, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_ALPHA16, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_INTENSITY8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_INTENSITY4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_INTENSITY12, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_INTENSITY16, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE4_ALPHA4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE6_ALPHA2, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE12_ALPHA4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE12_ALPHA12, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE16_ALPHA16, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { 1, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { 2, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { 3, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { 4, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGB, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_LUMINANCE, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_ALPHA, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_INTENSITY, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_LUMINANCE_ALPHA, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_SRGB8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN }, { GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_SLUMINANCE8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_SLUMINANCE8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, PLAIN },
    /* unpack formats and types into GL_RGBA8 */
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA8, GL_BGR, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA8, GL_BGRA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA8, GL_LUMINANCE, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA8, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA8, GL_ALPHA, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA8, GL_RED, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA8, GL_GREEN, GL_UNSIGNED_BYTE, PLAIN },
    { GL_RGBA8, GL_BLUE, GL_UNSIGNED_BYTE, PLAIN }, { GL_RGBA8, GL_RGBA, GL_BYTE, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT, PLAIN }, { GL_RGBA8, GL_RGBA, GL_SHORT, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT, PLAIN }, { GL_RGBA8, GL_RGBA, GL_INT, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_FLOAT, PLAIN }, { GL_RGBA8, GL_BGR, GL_FLOAT, PLAIN },
    { GL_RGBA8, GL_LUMINANCE_ALPHA, GL_FLOAT, PLAIN }, { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, PLAIN },
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, PLAIN }, { GL_RGBA8, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, PLAIN },
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, PLAIN },
    { GL_RGBA8, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, PLAIN },
    { GL_RGBA8, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, PLAIN }, { GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, PLAIN },
    { GL_RGBA8, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, PLAIN }, { GL_RGBA8, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, PLAIN },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, PLAIN },
    { GL_RGBA8, GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, PLAIN },
    /* unsized internal formats from packed and float data */
    { GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, PLAIN }, { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, PLAIN },
    { GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, PLAIN },
    { GL_RGBA, GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, PLAIN }, { GL_RGBA, GL_RGBA, GL_FLOAT, PLAIN },
    { GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, PLAIN }, { GL_RGB10_A2, GL_RGBA, GL_FLOAT, PLAIN },
    /* unpack state */
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE, { 1, 0, 0, 0, 0 } },
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE, { 2, 0, 0, 0, 0 } },
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE, { 8, 0, 0, 0, 0 } },
    { GL_RGBA8, GL_LUMINANCE, GL_UNSIGNED_BYTE, { 8, 0, 0, 0, 0 } },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, { 4, 9, 3, 2, 0 } },
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_BYTE, { 8, 7, 1, 1, 0 } },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, { 2, 6, 1, 0, 0 } },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT, { 4, 0, 0, 0, 1 } },
    { GL_RGBA8, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, { 2, 0, 0, 0, 1 } },
    { GL_RGBA8, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, { 4, 0, 0, 0, 1 } },
    { GL_RGBA8, GL_RGBA, GL_FLOAT, { 4, 7, 2, 1, 0 } },
    { GL_RGBA8, GL_RGBA, GL_FLOAT, { 4, 7, 0, 0, 1 } },
};

/* The last two cells: uploads from a pixel unpack buffer (GL_RGB5_A1 from
 * GL_BGRA / GL_UNSIGNED_SHORT_1_5_5_5_REV with row length and skips;
 * GL_RGBA8 by glTexSubImage2D from GL_RGBA / GL_FLOAT). */
static const upload_case pbo_cases[2] = {
    { GL_RGB5_A1, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, { 4, 7, 1, 2, 0 } },
    { GL_RGBA8, GL_RGBA, GL_FLOAT, PLAIN },
};

int main(int argc, char **argv)
{
    const int n = (int)(sizeof cases / sizeof cases[0]) + 2, cols = 10, cell = 24;
    const int rows = (n + cols - 1) / cols;
    GLuint name;
    int i;
    scene_begin(argc, argv, cols * cell, rows * cell);
    scene_ortho_pixels();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    /* the fragment colour shows through GL_ALPHA textures' colour */
    glColor4f(0.55f, 0.45f, 0.35f, 1.0f);
    for (i = 0; i < n; i++) {
        const upload_case *k = i < n - 2 ? &cases[i] : &pbo_cases[i - (n - 2)];
        float x0 = (float)(i % cols * cell + 2), y0 = (float)((rows - 1 - i / cols) * cell + 4);
        name = tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
        if (i < n - 2)
            upload(k->internal, k->format, k->type, &k->u);
        else
            upload_pbo(k->internal, k->format, k->type, &k->u, i == n - 1);
        glBegin(GL_QUADS);
        glTexCoord2f(0.0f, 0.0f); glVertex2f(x0, y0);
        glTexCoord2f(1.0f, 0.0f); glVertex2f(x0 + 4 * W, y0);
        glTexCoord2f(1.0f, 1.0f); glVertex2f(x0 + 4 * W, y0 + 4 * H);
        glTexCoord2f(0.0f, 1.0f); glVertex2f(x0, y0 + 4 * H);
        glEnd();
        glDeleteTextures(1, &name);
    }
    return scene_end();
}
