/*
 * fb_common.h - helpers for the selection and feedback programs.
 *
 * Each program in reference/feedback/ is a plain legacy GL program built
 * against Mesa's OSMesa. It renders in GL_SELECT or GL_FEEDBACK mode and
 * prints the returned buffers as text on stdout: the runner runs it once on
 * Mesa and once on libglfixed's drop-in and diffs the two outputs exactly.
 * Floats are printed with %.9g (enough to tell every float apart).
 */
#ifndef GLFX_FB_COMMON_H
#define GLFX_FB_COMMON_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

static void *fb_pixels;
static OSMesaContext fb_ctx;

/* An RGBA context with a 24-bit depth buffer, width x height, current. */
static inline void fb_begin(int width, int height) {
    fb_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    fb_pixels = calloc((size_t)width * height, 4);
    if (!fb_ctx || !fb_pixels ||
        !OSMesaMakeCurrent(fb_ctx, fb_pixels, GL_UNSIGNED_BYTE, width, height)) {
        fprintf(stderr, "cannot make an OSMesa context current\n");
        exit(1);
    }
}

static inline int fb_end(void) {
    GLenum e = glGetError();
    printf("final error 0x%04x\n", e);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(fb_ctx);
    free(fb_pixels);
    return 0;
}

static inline void fb_error(const char *where) {
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) printf("%s: error 0x%04x\n", where, e);
}

/* The selection buffer: `hits` records (or -1 on overflow: the whole buffer
 * of `size` words is printed raw). */
static inline void fb_print_select(const char *title, GLint hits, const GLuint *buf, GLint size) {
    printf("select %s: hits %d\n", title, hits);
    if (hits < 0) {
        for (GLint i = 0; i < size; ++i) printf("  [%d] %u\n", i, buf[i]);
        return;
    }
    GLint at = 0;
    for (GLint h = 0; h < hits && at + 3 <= size; ++h) {
        GLuint n = buf[at];
        printf("  hit %d: names %u z1 %u z2 %u :", h, n, buf[at + 1], buf[at + 2]);
        at += 3;
        for (GLuint k = 0; k < n && at < size; ++k) printf(" %u", buf[at++]);
        printf("\n");
    }
}

static inline const char *fb_token_name(GLfloat t) {
    switch ((int)t) {
        case GL_PASS_THROUGH_TOKEN: return "PASS_THROUGH";
        case GL_POINT_TOKEN: return "POINT";
        case GL_LINE_TOKEN: return "LINE";
        case GL_LINE_RESET_TOKEN: return "LINE_RESET";
        case GL_POLYGON_TOKEN: return "POLYGON";
        case GL_BITMAP_TOKEN: return "BITMAP";
        case GL_DRAW_PIXEL_TOKEN: return "DRAW_PIXEL";
        case GL_COPY_PIXEL_TOKEN: return "COPY_PIXEL";
        default: return NULL;
    }
}

/* Values per vertex for a feedback type (GL 2.1 table 5.1). */
static inline int fb_vertex_words(GLenum type) {
    switch (type) {
        case GL_2D: return 2;
        case GL_3D: return 3;
        case GL_3D_COLOR: return 7;
        case GL_3D_COLOR_TEXTURE: return 11;
        case GL_4D_COLOR_TEXTURE: return 12;
        default: return 0;
    }
}

/* The feedback buffer, parsed by token; `count` values (or -1: the whole
 * buffer of `size` values raw). Raw too if parsing fails. */
static inline void fb_print_feedback(const char *title, GLenum type, GLint count, const GLfloat *buf, GLint size) {
    printf("feedback %s: count %d\n", title, count);
    int raw = count < 0;
    const int vw = fb_vertex_words(type);
    GLint at = 0;
    while (!raw && at < count) {
        const char *name = fb_token_name(buf[at]);
        if (!name) { raw = 1; break; }
        int t = (int)buf[at++];
        int vertices = 0;
        printf("  %s", name);
        if (t == GL_PASS_THROUGH_TOKEN) {
            if (at < count) printf(" %.9g", buf[at]);
            at++;
        } else if (t == GL_POLYGON_TOKEN) {
            if (at < count) { vertices = (int)buf[at]; printf(" %d", vertices); }
            at++;
        } else if (t == GL_LINE_TOKEN || t == GL_LINE_RESET_TOKEN) {
            vertices = 2;
        } else {
            vertices = 1;
        }
        printf("\n");
        for (int v = 0; v < vertices; ++v) {
            printf("    ");
            for (int k = 0; k < vw && at < count; ++k) printf(" %.9g", buf[at++]);
            printf("\n");
        }
    }
    if (raw) {
        GLint n = count < 0 ? size : count;
        for (GLint i = 0; i < n; ++i) printf("  [%d] %.9g\n", i, buf[i]);
    }
}

#endif
