/*
 * egl_window_scene - an EGL program on X11, made the way Debian's
 * xscreensaver GL hacks make theirs: an X window with the config's native
 * visual, an OpenGL (compatibility) context, GL 1.x drawing. It draws a lit
 * scene (spheres and a torus, glBegin/glEnd and glDrawElements, two lights)
 * for FRAMES frames with eglSwapBuffers, then reads the window back from the
 * X server with XGetImage and writes it.
 *
 * usage: egl_window_scene OUT_PREFIX [FRAMES] [options]
 *   --get-display       eglGetDisplay(x11 Display) instead of
 *                       eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, ...)
 *   --window-surface    eglCreateWindowSurface instead of
 *                       eglCreatePlatformWindowSurface
 *   --resize            after half the frames, XResizeWindow to 256x200 and
 *                       wait for its ConfigureNotify; the later frames draw at
 *                       that size and the surface must follow its window
 *   --rss               print the memory use every 100 frames and at the end
 * writes OUT_PREFIX.glfx (the dump format of reference/scenes/scene.h).
 * Exit status: 0 drawn and written, 1 usage, 2 failure (message on stderr).
 */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "egl_common.h"
#include "program_common.h"
#include "program_x11.h"

enum { WIDTH = 320, HEIGHT = 240, RESIZED_WIDTH = 256, RESIZED_HEIGHT = 200 };
static const char *const kProgram = "egl_window_scene";

static Display *g_x11;  /* for visual_ok, which eglChooseConfig's filter calls */

/* The config's native visual must exist on the screen, 24 or 32 deep. */
static int visual_ok(EGLDisplay dpy, EGLConfig config)
{
    EGLint id = 0;
    if (!eglGetConfigAttrib(dpy, config, EGL_NATIVE_VISUAL_ID, &id) || id == 0) return 0;
    XVisualInfo tmpl;
    memset(&tmpl, 0, sizeof tmpl);
    tmpl.visualid = (VisualID)id;
    int n = 0;
    XVisualInfo *vi = XGetVisualInfo(g_x11, VisualIDMask, &tmpl, &n);
    const int ok = vi && n > 0 && (vi->depth == 24 || vi->depth == 32) && vi->class == TrueColor;
    if (vi) XFree(vi);
    return ok;
}

/* Resizes the window and waits until the server has done it. */
static void resize_window(Display *x11, Window window, int width, int height)
{
    XResizeWindow(x11, window, (unsigned)width, (unsigned)height);
    XEvent event;
    do XWindowEvent(x11, window, StructureNotifyMask, &event);
    while (event.type != ConfigureNotify || event.xconfigure.width != width ||
           event.xconfigure.height != height);
}

/* EGL_WIDTH and EGL_HEIGHT of the surface must be width x height. */
static int check_surface_size(EGLDisplay dpy, EGLSurface surface, int width, int height)
{
    EGLint w = 0, h = 0;
    if (egl_check(kProgram, "eglQuerySurface(EGL_WIDTH)", eglQuerySurface(dpy, surface, EGL_WIDTH, &w)) ||
        egl_check(kProgram, "eglQuerySurface(EGL_HEIGHT)", eglQuerySurface(dpy, surface, EGL_HEIGHT, &h)))
        return -1;
    if (w != width || h != height) {
        fprintf(stderr, "%s: the surface is %dx%d, not %dx%d\n", kProgram, w, h, width, height);
        return -1;
    }
    return 0;
}

static Window create_window(Display *x11, EGLDisplay dpy, EGLConfig config)
{
    EGLint id = 0;
    eglGetConfigAttrib(dpy, config, EGL_NATIVE_VISUAL_ID, &id);
    XVisualInfo tmpl;
    memset(&tmpl, 0, sizeof tmpl);
    tmpl.visualid = (VisualID)id;
    int n = 0;
    XVisualInfo *vi = XGetVisualInfo(x11, VisualIDMask, &tmpl, &n);
    if (!vi || n < 1) {
        fprintf(stderr, "%s: no X visual 0x%x\n", kProgram, (unsigned)id);
        return 0;
    }
    const Window root = RootWindow(x11, vi->screen);
    XSetWindowAttributes attrs;
    memset(&attrs, 0, sizeof attrs);
    attrs.colormap = XCreateColormap(x11, root, vi->visual, AllocNone);
    attrs.border_pixel = 0;
    attrs.background_pixel = 0;
    attrs.event_mask = StructureNotifyMask | ExposureMask;
    const Window window =
        XCreateWindow(x11, root, 0, 0, WIDTH, HEIGHT, 0, vi->depth, InputOutput, vi->visual,
                      CWColormap | CWBorderPixel | CWBackPixel | CWEventMask, &attrs);
    XFree(vi);
    XStoreName(x11, window, kProgram);
    XMapWindow(x11, window);
    /* Wait until the server has mapped it, so XGetImage can read it. */
    XEvent event;
    do XWindowEvent(x11, window, StructureNotifyMask, &event);
    while (event.type != MapNotify);
    return window;
}

int main(int argc, char **argv)
{
    const char *prefix = NULL;
    int frames = 10, positional = 0, get_display = 0, window_surface = 0, rss = 0, resize = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--get-display") == 0) get_display = 1;
        else if (strcmp(argv[i], "--resize") == 0) resize = 1;
        else if (strcmp(argv[i], "--window-surface") == 0) window_surface = 1;
        else if (strcmp(argv[i], "--rss") == 0) rss = 1;
        else if (argv[i][0] != '-' && positional == 0) prefix = argv[i], positional++;
        else if (argv[i][0] != '-' && positional == 1 && (frames = program_frames_arg(argv[i], 10)) > 0)
            positional++;
        else { positional = -1; break; }
    }
    if (positional < 1) {
        fprintf(stderr,
                "usage: %s OUT_PREFIX [FRAMES] [--get-display] [--window-surface] [--resize] [--rss]\n",
                kProgram);
        return 1;
    }

    Display *x11 = g_x11 = XOpenDisplay(NULL);
    if (!x11) {
        fprintf(stderr, "%s: cannot open the X display (DISPLAY=%s)\n", kProgram,
                getenv("DISPLAY") ? getenv("DISPLAY") : "");
        return 2;
    }
    EGLDisplay dpy;
    if (get_display) {
        dpy = eglGetDisplay((EGLNativeDisplayType)x11);
        if (egl_check(kProgram, "eglGetDisplay(X11 Display)", dpy != EGL_NO_DISPLAY)) return 2;
    } else {
        dpy = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, x11, NULL);
        if (egl_check(kProgram, "eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR)", dpy != EGL_NO_DISPLAY))
            return 2;
    }
    EGLint major = 0, minor = 0;
    if (egl_check(kProgram, "eglInitialize", eglInitialize(dpy, &major, &minor))) return 2;
    egl_print_strings(dpy);
    if (egl_check(kProgram, "eglBindAPI(EGL_OPENGL_API)", eglBindAPI(EGL_OPENGL_API))) return 2;

    EGLConfig config;
    if (egl_choose_config(kProgram, dpy, EGL_WINDOW_BIT, -1, visual_ok, &config)) return 2;
    const EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (egl_check(kProgram, "eglCreateContext", context != EGL_NO_CONTEXT)) return 2;

    Window window = create_window(x11, dpy, config);
    if (!window) return 2;
    EGLSurface surface;
    if (window_surface) {
        surface = eglCreateWindowSurface(dpy, config, (EGLNativeWindowType)window, NULL);
        if (egl_check(kProgram, "eglCreateWindowSurface", surface != EGL_NO_SURFACE)) return 2;
    } else {
        surface = eglCreatePlatformWindowSurface(dpy, config, &window, NULL);
        if (egl_check(kProgram, "eglCreatePlatformWindowSurface", surface != EGL_NO_SURFACE)) return 2;
    }
    if (egl_check(kProgram, "eglMakeCurrent", eglMakeCurrent(dpy, surface, surface, context))) return 2;
    if (egl_check(kProgram, "eglSwapInterval(0)", eglSwapInterval(dpy, 0))) return 2;
    if (check_surface_size(dpy, surface, WIDTH, HEIGHT)) return 2;
    if (eglGetCurrentContext() != context || eglGetCurrentSurface(EGL_DRAW) != surface ||
        eglGetCurrentDisplay() != dpy) {
        fprintf(stderr, "%s: eglGetCurrent* do not name what eglMakeCurrent made current\n", kProgram);
        return 2;
    }
    if (program_print_renderer() != 0) return 2;

    program_lights_setup();
    int width = WIDTH, height = HEIGHT;
    for (int frame = 0; frame < frames; frame++) {
        if (resize && frame == frames / 2) {
            resize_window(x11, window, RESIZED_WIDTH, RESIZED_HEIGHT);
            width = RESIZED_WIDTH;
            height = RESIZED_HEIGHT;
        }
        program_draw_egl_scene(width, height, frame);
        if (egl_check(kProgram, "eglSwapBuffers", eglSwapBuffers(dpy, surface))) return 2;
        if (rss && ((frame + 1) % 100 == 0 || frame + 1 == frames)) program_report_rss(frame + 1);
    }
    glFinish();
    if (check_surface_size(dpy, surface, width, height)) return 2;

    int status = 0;
    unsigned char *rgba = malloc((size_t)width * height * 4);
    if (!rgba || program_read_window(x11, window, width, height, rgba) != 0 ||
        program_write_dump(prefix, width, height, rgba, 3, frames) != 0)
        status = 2;
    else
        printf("covered pixels: %ld of %d\n", program_covered_pixels(width, height, rgba), width * height);
    free(rgba);

    if (egl_check(kProgram, "eglMakeCurrent(none)",
                  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT)) ||
        egl_check(kProgram, "eglDestroySurface", eglDestroySurface(dpy, surface)) ||
        egl_check(kProgram, "eglDestroyContext", eglDestroyContext(dpy, context)) ||
        egl_check(kProgram, "eglTerminate", eglTerminate(dpy)) ||
        egl_check(kProgram, "eglReleaseThread", eglReleaseThread()))
        status = 2;
    XDestroyWindow(x11, window);
    XCloseDisplay(x11);
    return status;
}
