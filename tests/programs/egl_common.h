/*
 * egl_common.h - error reporting and config choice shared by the EGL programs.
 */
#ifndef GLFX_EGL_COMMON_H
#define GLFX_EGL_COMMON_H

#include <EGL/egl.h>
#include <EGL/eglext.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The name of an EGL error code ("EGL_BAD_MATCH"), or "unknown". */
const char *egl_error_name(EGLint error);

/* eglGetError() after `step`: 0 when EGL_SUCCESS, else prints
 * "<program>: <step> failed: <error>" and returns -1. `ok` is the call's own
 * answer (EGL_TRUE or a non-null handle); a false `ok` with EGL_SUCCESS is
 * an error too. */
int egl_check(const char *program, const char *step, int ok);

/* eglChooseConfig for RGB8 + depth 24 with `surface_type` and
 * EGL_OPENGL_BIT, then the first config that has exactly 8 bits of red,
 * green and blue (Mesa sorts 10-bit configs first on the surfaceless
 * platform) and, when want_alpha >= 0, exactly that many alpha bits.
 * When visual_ok is given it must accept the config too (the window program
 * checks the native visual). Prints the chosen config. Returns 0 or -1. */
int egl_choose_config(const char *program, EGLDisplay dpy, EGLint surface_type, int want_alpha,
                      int (*visual_ok)(EGLDisplay, EGLConfig), EGLConfig *config);

/* Prints EGL_VENDOR and EGL_VERSION (stdout). */
void egl_print_strings(EGLDisplay dpy);

#ifdef __cplusplus
}
#endif
#endif
