/*
 * scene.h - tiny helper library for the libglfixed reference scenes.
 *
 * Each scene is an ordinary legacy GL 1.x program:
 *     int main(int argc, char **argv)
 * argv[1] = output path prefix.  The same executable is run once on Mesa and
 * once on libglfixed (via LD_LIBRARY_PATH); glfx_compare compares the dumps.
 *
 * Typical scene:
 *     int main(int argc, char **argv) {
 *         scene_begin(argc, argv, 128, 128);
 *         scene_ortho_pixels();
 *         glBegin(GL_TRIANGLES); ... glEnd();
 *         return scene_end();
 *     }
 *
 * KEY colour and coverage
 * -----------------------
 * scene_clear() clears the colour buffer to the KEY colour
 *     RGBA = (3/255, 5/255, 7/255, 0)      (bytes 3, 5, 7, 0)
 * and the depth buffer to 1.0.  A pixel is "covered" when its colour differs
 * from the KEY colour in any channel the pixel format stores (R,G,B for
 * OSMESA_RGB/OSMESA_BGR, R,G,B,A otherwise) OR its depth value differs from the
 * depth value a freshly cleared buffer holds (recorded by scene_begin; only
 * where a depth buffer exists).  So avoid drawing in the exact KEY colour
 * unless the geometry also writes depth.
 *
 * Output files (written by scene_end / scene_readpixels_check)
 * ------------------------------------------------------------
 *   <prefix>.glfx        the client colour buffer + the depth buffer
 *   <prefix>.readpixels  glReadPixels(GL_RGBA, GL_UNSIGNED_BYTE) result
 * Both have the same layout:
 *   line 1: "GLFX1 <w> <h> <coverage_channels> <depth_w> <depth_h> <depth_bytes>
 *            <cleared_depth> <guard_damage>\n"
 *   line 2: "info key=value ...\n"  (GL/OSMesa integer state, compared
 *            informationally)
 *   w*h*4 bytes RGBA8, top row first (alpha = 255 for formats without alpha)
 *   depth_w*depth_h*depth_bytes bytes: raw depth values (native byte order),
 *            top row first.
 * guard_damage counts bytes of the client buffer outside the image area
 * (row-length padding and a guard zone past the end) that were modified.
 *
 * Facts measured on Mesa 22.3.6 / llvmpipe that the dump relies on:
 *   - OSMesaGetDepthBuffer memory is tightly packed (width*bytesPerValue per
 *     row) and row 0 is the BOTTOM row (GL window y = 0) whatever OSMESA_Y_UP
 *     says; the dump flips it to top-first.
 *   - OSMESA_RGB + GL_UNSIGNED_BYTE renders corrupted pixels on llvmpipe
 *     (softpipe is fine).  So when the runner marks the Mesa side
 *     (GLFX_SIDE=mesa), an OSMESA_RGB scene renders into an OSMESA_RGBA
 *     context and is dumped as RGB (alpha 255, GL_ALPHA_BITS reported 0, info
 *     "mesa_rgb_via_rgba=1").  GLFX_RGB_RAW=1 shows Mesa's real RGB output.
 *   - OSMESA_BGR + GL_UNSIGNED_BYTE is refused by OSMesaMakeCurrent (see
 *     scene_begin_try).
 *   - depth_bits 1..15 gives no depth buffer, 16..23 gives 16-bit values
 *     (bytesPerValue 2, cleared = 0xffff), >= 24 gives 24-bit values in 32-bit
 *     words (bytesPerValue 4, cleared = 0x00ffffff, top byte 0).
 */
#ifndef GLFX_SCENE_H
#define GLFX_SCENE_H

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1   /* glProvokingVertex etc. */
#endif
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int width, height;     /* buffer size */
    GLenum format;         /* OSMESA_RGBA (default when 0), OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB, OSMESA_BGR,
                              OSMESA_RGB_565 (with scene_set_buffer_type(GL_UNSIGNED_SHORT_5_6_5)) */
    int depth_bits;        /* passed to OSMesaCreateContextExt; use 24 unless testing otherwise; -1 means default 24 */
    int y_up;              /* OSMESA_Y_UP value; default 1 (pass -1 for "don't call OSMesaPixelStore") */
    int row_length;        /* OSMESA_ROW_LENGTH in pixels, 0 = don't set */
} scene_options;

/* The stencil bits the next scene_begin* asks OSMesaCreateContextExt for
 * (default 0: no stencil buffer). */
void scene_set_stencil_bits(int bits);
/* The type the next scene_begin* gives OSMesaMakeCurrent (default
 * GL_UNSIGNED_BYTE): GL_UNSIGNED_SHORT or GL_FLOAT (16-bit unorm or float
 * channels, stored R, G, B(, A) whatever the format), or
 * GL_UNSIGNED_SHORT_5_6_5 with format OSMESA_RGB_565. The dump then holds the
 * buffer's own values and glfx_compare counts differences in units of the
 * format's least significant bit (16-bit: 1/65535; 5-6-5: 1/31 or 1/63;
 * float: one unit in the last place); scene_readpixels_check reads 16-bit
 * and float buffers as GL_UNSIGNED_SHORT and GL_FLOAT. The KEY is the clear
 * to (3, 5, 7, 0)/255 in the buffer's precision (5-6-5: 0, 1, 1). */
void scene_set_buffer_type(GLenum type);

/* RGBA, 24-bit depth, y_up default. */
void scene_begin(int argc, char **argv, int width, int height);
/* Before scene_begin*: the accumulation bits OSMesaCreateContextExt is asked for (default 0). */
void scene_set_accum_bits(int bits);
/* Creates the context (OSMesaCreateContextExt), mallocs the client buffer
 * (row_length pixels per row), OSMesaMakeCurrent(GL_UNSIGNED_BYTE),
 * OSMesaPixelStore as asked, glViewport(0,0,w,h), scene_clear().
 * Any OSMesa failure prints a message and exits with status 2. */
void scene_begin_ext(int argc, char **argv, const scene_options *opts);
/* Like scene_begin_ext, but when OSMesaCreateContextExt or OSMesaMakeCurrent
 * refuses the options it returns -1 instead of exiting (0 on success).  The
 * scene must then skip its GL calls; scene_end() still writes a dump (all KEY,
 * info "refused=create|makecurrent"), so "both refuse" compares equal and
 * "only one refuses" shows up as a coverage mismatch.  (Mesa 22 refuses
 * OSMESA_BGR with GL_UNSIGNED_BYTE in OSMesaMakeCurrent.) */
int  scene_begin_try(int argc, char **argv, const scene_options *opts);
/* glClearColor(KEY) + glClearDepth(1.0) + glClear(COLOR|DEPTH). */
void scene_clear(void);
/* glFinish, dumps <prefix>.glfx, destroys the context, returns 0
 * (so main can `return scene_end();`). */
int  scene_end(void);
/* glReadPixels(0,0,w,h,GL_RGBA,GL_UNSIGNED_BYTE) now, written to
 * <prefix>.readpixels (flipped to top row first). */
void scene_readpixels_check(void);

/* ---- conveniences (additions) ---- */
#define SCENE_KEY_R 3
#define SCENE_KEY_G 5
#define SCENE_KEY_B 7
#define SCENE_KEY_A 0
int  scene_width(void);
int  scene_height(void);
/* PROJECTION = glOrtho(0,w,0,h,-1,1) (one unit = one pixel, z in [-1,1]),
 * MODELVIEW = identity; leaves the matrix mode at GL_MODELVIEW. */
void scene_ortho_pixels(void);
/* Deterministic LCG (same sequence everywhere). */
void     scene_srand(unsigned int seed);
unsigned scene_rand(void);                  /* 0 .. 2^31-1 */
float    scene_randf(float lo, float hi);   /* uniform in [lo, hi) */

#ifdef __cplusplus
}
#endif
#endif
