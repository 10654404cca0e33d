/* An EGL program on an X11 window, as Debian's xscreensaver hacks make theirs:
   eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR), a configuration whose native
   visual is the window's, eglCreatePlatformWindowSurface, the probes' scene
   (egl_probe_scene.h), eglSwapBuffers, then the window read back with
   XGetImage. Built against the system's libEGL and libGL; run once on Mesa
   and once on the drop-in under the same Xvfb (egl_window_compare.sh).
   Usage: egl_window_probe <out.rgba> [flat|smooth] [frames]: with a frame
   count it draws and swaps that many frames first and prints its resident
   memory after a tenth of them and at the end ("rss growth"). */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "egl_probe_scene.h"

static long residentKiB(void) {
  long pages = 0, resident = 0;
  FILE* f = fopen("/proc/self/statm", "r");
  if (f && fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
  if (f) fclose(f);
  return resident * 4;
}

int main(int argc, char** argv) {
  if (argc < 2) return fprintf(stderr, "usage: egl_window_probe out.rgba [flat]\n"), 2;
  const int smooth = !(argc > 2 && strcmp(argv[2], "flat") == 0);
  Display* x = XOpenDisplay(NULL);
  if (!x) return fprintf(stderr, "no X display\n"), 1;
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, x, NULL);
  if (!eglInitialize(dpy, NULL, NULL)) return fprintf(stderr, "eglInitialize failed\n"), 1;
  /* 8 bits of red, no alpha, the default visual (see egl_pbuffer_probe.c on
     Mesa's 10-bit configurations). */
  const EGLint attribs[] = {EGL_SURFACE_TYPE,
                            EGL_WINDOW_BIT,
                            EGL_RENDERABLE_TYPE,
                            EGL_OPENGL_BIT,
                            EGL_RED_SIZE,
                            8,
                            EGL_DEPTH_SIZE,
                            16,
                            EGL_NONE};
  EGLConfig configs[512], config = NULL;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, attribs, configs, 512, &n)) return fprintf(stderr, "eglChooseConfig failed\n"), 1;
  const VisualID defaultVisual = XVisualIDFromVisual(DefaultVisual(x, DefaultScreen(x)));
  for (int i = 0; i < n && !config; ++i) {
    EGLint red = 0, alpha = -1, visual = 0;
    eglGetConfigAttrib(dpy, configs[i], EGL_RED_SIZE, &red);
    eglGetConfigAttrib(dpy, configs[i], EGL_ALPHA_SIZE, &alpha);
    eglGetConfigAttrib(dpy, configs[i], EGL_NATIVE_VISUAL_ID, &visual);
    if (red == 8 && alpha == 0 && (VisualID)visual == defaultVisual) config = configs[i];
  }
  if (!config) return fprintf(stderr, "no 8-bit configuration of the default visual\n"), 1;
  Window win = XCreateSimpleWindow(x, DefaultRootWindow(x), 0, 0, W, H, 0, 0, 0);
  XMapWindow(x, win);
  XSync(x, False);
  EGLSurface surface = eglCreatePlatformWindowSurface(dpy, config, &win, NULL);
  if (!eglBindAPI(EGL_OPENGL_API)) return fprintf(stderr, "eglBindAPI failed\n"), 1;
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  if (!surface || !ctx || !eglMakeCurrent(dpy, surface, surface, ctx))
    return fprintf(stderr, "no window context\n"), 1;
  const int frames = argc > 3 ? atoi(argv[3]) : 0;
  long rssEarly = 0;
  for (int i = 0; i < frames; ++i) {
    drawScene(smooth);
    if (!eglSwapBuffers(dpy, surface)) return fprintf(stderr, "eglSwapBuffers failed\n"), 1;
    if (i == frames / 10) rssEarly = residentKiB();
  }
  if (frames > 0)
    printf("rss growth %ld KiB over %d frames\n", residentKiB() - rssEarly, frames - frames / 10);
  drawScene(smooth);
  if (!eglSwapBuffers(dpy, surface)) return fprintf(stderr, "eglSwapBuffers failed\n"), 1;
  eglWaitClient();
  XSync(x, False);
  XImage* image = XGetImage(x, win, 0, 0, W, H, AllPlanes, ZPixmap);
  if (!image) return fprintf(stderr, "XGetImage failed\n"), 1;
  static unsigned char pixels[W * H * 4];
  for (int y = 0; y < H; ++y)
    for (int xx = 0; xx < W; ++xx) {
      const unsigned long p = XGetPixel(image, xx, H - 1 - y); /* row 0 at the bottom, as glReadPixels */
      unsigned char* q = pixels + (y * W + xx) * 4;
      q[0] = (p >> 16) & 255;
      q[1] = (p >> 8) & 255;
      q[2] = p & 255;
      q[3] = 255;
    }
  XDestroyImage(image);
  FILE* f = fopen(argv[1], "wb");
  if (!f || fwrite(pixels, 1, sizeof pixels, f) != sizeof pixels) return fprintf(stderr, "cannot write\n"), 1;
  fclose(f);
  printf("renderer %s, vendor %s\n", (const char*)glGetString(GL_RENDERER), eglQueryString(dpy, EGL_VENDOR));
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, surface);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  XDestroyWindow(x, win);
  XCloseDisplay(x);
  return 0;
}
