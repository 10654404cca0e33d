/*
 * egl_pbuffer_scene - an offscreen EGL program with no X server at all, the
 * way renderers that used OSMesa move to EGL: a pbuffer on Mesa's
 * surfaceless platform (or on the default display), an OpenGL
 * (compatibility) context, the lit scene of egl_window_scene, read back
 * with glReadPixels after each of FRAMES frames; the last one is written.
 *
 * usage: egl_pbuffer_scene OUT_PREFIX [FRAMES] [options]
 *   (default)           eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA,
 *                       EGL_DEFAULT_DISPLAY) and a 256x256 pbuffer
 *   --default-display   eglGetDisplay(EGL_DEFAULT_DISPLAY) and a pbuffer
 *   --no-surface        the surfaceless platform and eglMakeCurrent with
 *                       EGL_NO_SURFACE: no default framebuffer, so it checks
 *                       only that the context works (strings, state, a
 *                       display list, no GL error) and writes no picture
 *   --rss               print the memory use every 100 frames and at the end
 *   --leak-kb N         keep N kB more memory each frame, never freed: the
 *                       harness checks that its soak test catches a leak
 * writes OUT_PREFIX.glfx (the dump format of reference/scenes/scene.h).
 * Exit status: 0 drawn and written, 1 usage, 2 failure (message on stderr).
 */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "egl_common.h"
#include "program_common.h"

enum { SIZE = 256 };
static const char *const kProgram = "egl_pbuffer_scene";

static int has_extension(const char *list, const char *name)
{
    const size_t len = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)) != NULL; p += len)
        if ((p == list || p[-1] == ' ') && (p[len] == ' ' || p[len] == '\0')) return 1;
    return 0;
}

/* With no surface bound there is no framebuffer to draw into: check what a
 * context gives without one. */
static int check_context_without_surface(void)
{
    if (program_print_renderer() != 0) return -1;
    GLint max_lights = 0;
    glGetIntegerv(GL_MAX_LIGHTS, &max_lights);
    program_lights_setup();
    const GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    program_sphere(0.5f, 8, 4);
    glEndList();
    const int ok = max_lights >= 8 && glIsEnabled(GL_LIGHTING) && glIsEnabled(GL_LIGHT1) &&
                   list != 0 && glIsList(list);
    glDeleteLists(list, 1);
    const GLenum error = glGetError();
    if (!ok || error != GL_NO_ERROR) {
        fprintf(stderr, "%s: context without a surface: GL_MAX_LIGHTS %d, state %s, GL error 0x%04x\n",
                kProgram, max_lights, ok ? "right" : "wrong", (unsigned)error);
        return -1;
    }
    printf("context without a surface: works\n");
    return 0;
}

/* --leak-kb: memory kept on purpose, written so that it is resident, and
 * chained so that the compiler cannot drop it. */
static void *volatile g_leaked;
static void leak(int kb)
{
    for (int i = 0; i < kb; i++) {
        void **block = malloc(1024);
        if (!block) return;
        memset(block, 0x5a, 1024);
        *block = g_leaked;
        g_leaked = block;
    }
}

static int draw_and_read(const char *prefix, int frames, int rss, int leak_kb)
{
    unsigned char *pixels = malloc((size_t)SIZE * SIZE * 4);
    unsigned char *top_first = malloc((size_t)SIZE * SIZE * 4);
    int status = pixels && top_first ? 0 : -1;
    program_lights_setup();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int frame = 0; status == 0 && frame < frames; frame++) {
        program_draw_egl_scene(SIZE, SIZE, frame);
        glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        leak(leak_kb);
        if (rss && ((frame + 1) % 100 == 0 || frame + 1 == frames)) program_report_rss(frame + 1);
    }
    if (status == 0) {
        const size_t row = (size_t)SIZE * 4;
        for (int y = 0; y < SIZE; y++) memcpy(&top_first[y * row], &pixels[(SIZE - 1 - y) * row], row);
        status = program_write_dump(prefix, SIZE, SIZE, top_first, 4, frames);
        if (status == 0)
            printf("covered pixels: %ld of %d\n", program_covered_pixels(SIZE, SIZE, top_first), SIZE * SIZE);
    }
    free(pixels);
    free(top_first);
    return status;
}

int main(int argc, char **argv)
{
    const char *prefix = NULL;
    int frames = 10, positional = 0, default_display = 0, no_surface = 0, rss = 0, leak_kb = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--leak-kb") == 0 && i + 1 < argc) leak_kb = atoi(argv[++i]);
        else if (strcmp(argv[i], "--default-display") == 0) default_display = 1;
        else if (strcmp(argv[i], "--no-surface") == 0) no_surface = 1;
        else if (strcmp(argv[i], "--rss") == 0) rss = 1;
        else if (argv[i][0] != '-' && positional == 0) prefix = argv[i], positional++;
        else if (argv[i][0] != '-' && positional == 1 && (frames = program_frames_arg(argv[i], 10)) > 0)
            positional++;
        else { positional = -1; break; }
    }
    if (positional < 1 || (default_display && no_surface)) {
        fprintf(stderr,
                "usage: %s OUT_PREFIX [FRAMES] [--default-display | --no-surface] [--rss] [--leak-kb N]\n",
                kProgram);
        return 1;
    }

    EGLDisplay dpy;
    if (default_display) {
        dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
        if (egl_check(kProgram, "eglGetDisplay(EGL_DEFAULT_DISPLAY)", dpy != EGL_NO_DISPLAY)) return 2;
    } else {
        const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!has_extension(client, "EGL_MESA_platform_surfaceless")) {
            fprintf(stderr, "%s: the client extensions do not name EGL_MESA_platform_surfaceless: %s\n",
                    kProgram, client ? client : "(null)");
            return 2;
        }
        dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        if (egl_check(kProgram, "eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)",
                      dpy != EGL_NO_DISPLAY))
            return 2;
    }
    EGLint major = 0, minor = 0;
    if (egl_check(kProgram, "eglInitialize", eglInitialize(dpy, &major, &minor))) return 2;
    egl_print_strings(dpy);
    if (no_surface && !has_extension(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        fprintf(stderr, "%s: the display does not offer EGL_KHR_surfaceless_context\n", kProgram);
        return 2;
    }
    if (egl_check(kProgram, "eglBindAPI(EGL_OPENGL_API)", eglBindAPI(EGL_OPENGL_API))) return 2;

    EGLConfig config;
    if (egl_choose_config(kProgram, dpy, EGL_PBUFFER_BIT, 8, NULL, &config)) return 2;
    const EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
    if (egl_check(kProgram, "eglCreateContext", context != EGL_NO_CONTEXT)) return 2;

    int status = 0;
    EGLSurface surface = EGL_NO_SURFACE;
    if (no_surface) {
        if (egl_check(kProgram, "eglMakeCurrent(EGL_NO_SURFACE)",
                      eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, context)))
            return 2;
        if (check_context_without_surface() != 0) status = 2;
    } else {
        const EGLint pbuffer_attribs[] = {EGL_WIDTH, SIZE, EGL_HEIGHT, SIZE, EGL_NONE};
        surface = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
        if (egl_check(kProgram, "eglCreatePbufferSurface", surface != EGL_NO_SURFACE)) return 2;
        if (egl_check(kProgram, "eglMakeCurrent", eglMakeCurrent(dpy, surface, surface, context))) return 2;
        EGLint w = 0, h = 0;
        if (egl_check(kProgram, "eglQuerySurface(EGL_WIDTH)", eglQuerySurface(dpy, surface, EGL_WIDTH, &w)) ||
            egl_check(kProgram, "eglQuerySurface(EGL_HEIGHT)", eglQuerySurface(dpy, surface, EGL_HEIGHT, &h)))
            return 2;
        if (w != SIZE || h != SIZE) {
            fprintf(stderr, "%s: the pbuffer is %dx%d, not %dx%d\n", kProgram, w, h, SIZE, SIZE);
            return 2;
        }
        if (program_print_renderer() != 0 || draw_and_read(prefix, frames, rss, leak_kb) != 0) status = 2;
    }

    if (egl_check(kProgram, "eglMakeCurrent(none)",
                  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT)) ||
        (surface != EGL_NO_SURFACE &&
         egl_check(kProgram, "eglDestroySurface", eglDestroySurface(dpy, surface))) ||
        egl_check(kProgram, "eglDestroyContext", eglDestroyContext(dpy, context)) ||
        egl_check(kProgram, "eglTerminate", eglTerminate(dpy)) ||
        egl_check(kProgram, "eglReleaseThread", eglReleaseThread()))
        status = 2;
    return status;
}
