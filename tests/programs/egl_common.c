/* egl_common.c - see egl_common.h. */
#include "egl_common.h"

#include <stdio.h>

const char *egl_error_name(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown";
    }
}

int egl_check(const char *program, const char *step, int ok)
{
    const EGLint error = eglGetError();
    if (error == EGL_SUCCESS && ok) return 0;
    fprintf(stderr, "%s: %s failed: %s (0x%04x)\n", program, step, egl_error_name(error),
            (unsigned)error);
    return -1;
}

static EGLint attrib(EGLDisplay dpy, EGLConfig config, EGLint name)
{
    EGLint value = -1;
    if (!eglGetConfigAttrib(dpy, config, name, &value)) return -1;
    return value;
}

int egl_choose_config(const char *program, EGLDisplay dpy, EGLint surface_type, int want_alpha,
                      int (*visual_ok)(EGLDisplay, EGLConfig), EGLConfig *config)
{
    const EGLint attribs[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                              EGL_ALPHA_SIZE, want_alpha > 0 ? want_alpha : 0,
                              EGL_DEPTH_SIZE, 24, EGL_SURFACE_TYPE, surface_type,
                              EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig configs[256];
    EGLint count = 0;
    if (egl_check(program, "eglChooseConfig", eglChooseConfig(dpy, attribs, configs, 256, &count)))
        return -1;
    for (EGLint i = 0; i < count; i++) {
        EGLConfig c = configs[i];
        if (attrib(dpy, c, EGL_RED_SIZE) != 8 || attrib(dpy, c, EGL_GREEN_SIZE) != 8 ||
            attrib(dpy, c, EGL_BLUE_SIZE) != 8)
            continue;
        if (want_alpha >= 0 && attrib(dpy, c, EGL_ALPHA_SIZE) != want_alpha) continue;
        if (visual_ok && !visual_ok(dpy, c)) continue;
        *config = c;
        printf("EGL config: id 0x%x, RGBA %d %d %d %d, depth %d, stencil %d, surfaces 0x%x, visual 0x%x"
               " (%d of %d matched)\n",
               (unsigned)attrib(dpy, c, EGL_CONFIG_ID), attrib(dpy, c, EGL_RED_SIZE),
               attrib(dpy, c, EGL_GREEN_SIZE), attrib(dpy, c, EGL_BLUE_SIZE),
               attrib(dpy, c, EGL_ALPHA_SIZE), attrib(dpy, c, EGL_DEPTH_SIZE),
               attrib(dpy, c, EGL_STENCIL_SIZE), (unsigned)attrib(dpy, c, EGL_SURFACE_TYPE),
               (unsigned)attrib(dpy, c, EGL_NATIVE_VISUAL_ID), (int)i + 1, (int)count);
        return egl_check(program, "eglGetConfigAttrib", 1);
    }
    fprintf(stderr, "%s: none of the %d configs eglChooseConfig returned has RGB 8 8 8%s\n", program,
            (int)count, visual_ok ? " and a usable visual" : "");
    return -1;
}

void egl_print_strings(EGLDisplay dpy)
{
    const char *vendor = eglQueryString(dpy, EGL_VENDOR);
    const char *version = eglQueryString(dpy, EGL_VERSION);
    printf("EGL_VENDOR: %s\nEGL_VERSION: %s\n", vendor ? vendor : "(null)", version ? version : "(null)");
}
