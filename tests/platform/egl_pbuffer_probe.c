/* An EGL pbuffer program with no X server: the surfaceless platform, a lit
   triangle in a pbuffer, read back with glReadPixels. Built against the
   system's libEGL and libGL (Mesa's), it runs once on Mesa and once with
   LD_LIBRARY_PATH naming the drop-in folder (libglfixed); it prints the EGL and
   GL facts it sees and writes the pixels to a file, and
   `egl_pbuffer_probe --compare a b` compares two such files within the
   fidelity bar (no pixel covered on one side only, >= 99.99% identical, no
   channel off by more than 1). */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "egl_probe_scene.h"

static void fact(const char* what, long value) { printf("%s: 0x%lx\n", what, value); }

int main(int argc, char** argv) {
  if (argc == 4 && strcmp(argv[1], "--compare") == 0) return comparePictures(argv[2], argv[3]);
  const char* out = argc > 1 ? argv[1] : "egl_pbuffer.rgba";
  /* "flat": the lit triangle flat-shaded; smooth by default. */
  const int smooth = !(argc > 2 && strcmp(argv[2], "flat") == 0);
  PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay =
      (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
  if (!getPlatformDisplay) return fprintf(stderr, "no eglGetPlatformDisplayEXT\n"), 1;
  EGLDisplay dpy = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) return fprintf(stderr, "eglInitialize failed\n"), 1;
  printf("EGL %d.%d, vendor %s\n", major, minor, eglQueryString(dpy, EGL_VENDOR));

  /* Errors and refusals. */
  fact("initial eglQueryAPI", eglQueryAPI());
  fact("eglBindAPI(EGL_OPENVG_API) returns", eglBindAPI(EGL_OPENVG_API));
  fact("  then eglGetError", eglGetError());
  EGLint n = -1;
  const EGLint windowDefault[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  eglChooseConfig(dpy, windowDefault, NULL, 0, &n);
  fact("configs for a window (default EGL_SURFACE_TYPE) on surfaceless", n);
  const EGLint bad[] = {0x7777, 1, EGL_NONE};
  fact("eglChooseConfig(unknown attribute) returns", eglChooseConfig(dpy, bad, NULL, 0, &n));
  fact("  then eglGetError", eglGetError());

  const EGLint attribs[] = {EGL_SURFACE_TYPE,
                            EGL_PBUFFER_BIT,
                            EGL_RENDERABLE_TYPE,
                            EGL_OPENGL_BIT,
                            EGL_RED_SIZE,
                            8,
                            EGL_DEPTH_SIZE,
                            16,
                            EGL_NONE};
  /* EGL 1.5 §3.4.1 sorts the larger sum of the requested colour sizes first,
     so Mesa answers with its 10-bit configurations before the 8-bit ones:
     take the first with 8 bits of red and no alpha, as libglfixed has. */
  EGLConfig configs[256], config = NULL;
  if (!eglChooseConfig(dpy, attribs, configs, 256, &n) || n < 1) return fprintf(stderr, "no config\n"), 1;
  EGLint red = 0, alphaBits = -1;
  eglGetConfigAttrib(dpy, configs[0], EGL_RED_SIZE, &red);
  fact("first config's red size", red);
  for (int i = 0; i < n && !config; ++i) {
    eglGetConfigAttrib(dpy, configs[i], EGL_RED_SIZE, &red);
    eglGetConfigAttrib(dpy, configs[i], EGL_ALPHA_SIZE, &alphaBits);
    if (red == 8 && alphaBits == 0) config = configs[i];
  }
  if (!config) return fprintf(stderr, "no 8-bit config\n"), 1;
  EGLint v;
  eglGetConfigAttrib(dpy, config, EGL_DEPTH_SIZE, &v);
  fact("chosen config: depth", v);
  eglGetConfigAttrib(dpy, config, EGL_ALPHA_SIZE, &v);
  fact("chosen config: alpha", v);
  eglGetConfigAttrib(dpy, config, EGL_NATIVE_VISUAL_ID, &v);
  fact("chosen config: native visual id", v);
  eglBindAPI(EGL_OPENGL_API);
  const EGLint core[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext coreCtx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, core);
  fact("core profile mask, no version: context made", coreCtx != EGL_NO_CONTEXT);
  if (coreCtx) eglDestroyContext(dpy, coreCtx);
  const EGLint pbAttribs[] = {EGL_WIDTH, W, EGL_HEIGHT, H, EGL_NONE};
  EGLSurface pb = eglCreatePbufferSurface(dpy, config, pbAttribs);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  if (!pb || !ctx || !eglMakeCurrent(dpy, pb, pb, ctx)) return fprintf(stderr, "no pbuffer context\n"), 1;
  eglQuerySurface(dpy, pb, EGL_RENDER_BUFFER, &v);
  fact("pbuffer EGL_RENDER_BUFFER", v);
  GLint drawBuffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
  fact("pbuffer GL_DRAW_BUFFER", drawBuffer);
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  printf("viewport %d %d %d %d\n", viewport[0], viewport[1], viewport[2], viewport[3]);
  fact("eglSwapBuffers on a pbuffer returns", eglSwapBuffers(dpy, pb));

  drawScene(smooth);
  static unsigned char pixels[W * H * 4];
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  fact("glGetError", glGetError());
  FILE* f = fopen(out, "wb");
  if (!f || fwrite(pixels, 1, sizeof pixels, f) != sizeof pixels)
    return fprintf(stderr, "cannot write %s\n", out), 1;
  fclose(f);
  printf("renderer %s\n", (const char*)glGetString(GL_RENDERER));
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, pb);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  return 0;
}
