/* The stencil test: every function against a ramp of stored values, and every
 * operation (INCR/DECR saturating and wrapping, INVERT, REPLACE, ZERO, KEEP)
 * under write masks, made visible by a pass that colours each stencil value. */
#include "scene.h"

static void rect(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0, y0); glVertex2f(x1, y0); glVertex2f(x1, y1); glVertex2f(x0, y1);
    glEnd();
}

/* Colours every pixel by its stencil value, one band of values a pass. */
static void show_stencil(void)
{
    int v;
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0xff);
    for (v = 0; v < 256; v += 1) {
        glStencilFunc(GL_EQUAL, v, 0xff);
        glColor3f((v & 7) / 7.0f, ((v >> 3) & 7) / 7.0f, (v >> 6) / 3.0f * 0.9f + 0.1f);
        rect(0, 0, 128, 128);
    }
}

int main(int argc, char **argv)
{
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const GLenum ops[8] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
    scene_options o = {128, 128, OSMESA_RGBA, 24, 1, 0};
    int i, j;
    scene_set_stencil_bits(8);
    scene_begin_ext(argc, argv, &o);
    scene_ortho_pixels();
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    /* A ramp of stored values: column j holds 32 j + 3 in the top half, j in 0..7. */
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    for (j = 0; j < 8; j++) {
        glStencilFunc(GL_ALWAYS, 32 * j + 3, 0xff);
        rect(16 * j, 64, 16 * j + 16, 128);
        glStencilFunc(GL_ALWAYS, (j & 1) ? 0xff : (j & 2 ? 0 : 0x80), 0xff);
        rect(16 * j, 0, 16 * j + 16, 64);
    }
    /* Top half: row i tests function i against the reference 100 (value mask
     * 0xf3 for the odd rows) and INCRs where it passes, INVERTs where it fails. */
    for (i = 0; i < 8; i++) {
        glStencilFunc(funcs[i], 100, (i & 1) ? 0xf3 : 0xff);
        glStencilOp(GL_INVERT, GL_KEEP, GL_INCR);
        rect(0, 64 + 8 * i, 128, 72 + 8 * i);
    }
    /* Bottom half: row i applies operation i (reference 0x5a), write mask
     * 0xff in the left half of each column and 0x3c in the right half. */
    for (i = 0; i < 8; i++) {
        glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, ops[i]);
        for (j = 0; j < 8; j++) {
            glStencilMask(0xff);
            rect(16 * j, 8 * i, 16 * j + 8, 8 * i + 8);
            glStencilMask(0x3c);
            rect(16 * j + 8, 8 * i, 16 * j + 16, 8 * i + 8);
        }
    }
    /* Twice more for the saturating and wrapping operations. */
    glStencilMask(0xff);
    for (i = 3; i < 8; i += 3) {
        glStencilOp(GL_KEEP, GL_KEEP, ops[i]);
        rect(0, 8 * i, 128, 8 * i + 4);
    }
    show_stencil();
    scene_readpixels_check();
    return scene_end();
}
