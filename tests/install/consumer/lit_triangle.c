/* A program from outside the tree: draws one lit triangle with OSMesa and
 * checks the pixel in its middle has the lit colour, not the clear colour.
 * Built against the installed library (CMakeLists.txt here, and glfixed.pc)
 * and, for the one-instance test, against Mesa's headers and libraries.
 *
 * lit_triangle --one-instance also checks that libGL.so.1 and libOSMesa.so.8
 * are loaded and resolve glClear to one address in one mapped file. */
#define _GNU_SOURCE /* dladdr, realpath */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kWidth = 32, kHeight = 32 };

static int checkOneInstance(void) {
  void *gl = dlopen("libGL.so.1", RTLD_NOW | RTLD_NOLOAD);
  void *osmesa = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_NOLOAD);
  if (!gl || !osmesa) {
    fprintf(stderr, "FAIL: libGL.so.1 %s, libOSMesa.so.8 %s\n", gl ? "loaded" : "not loaded",
            osmesa ? "loaded" : "not loaded");
    return 0;
  }
  void *glClearOfGL = dlsym(gl, "glClear");
  void *glClearOfOSMesa = dlsym(osmesa, "glClear");
  Dl_info inGL, inOSMesa;
  if (!glClearOfGL || !glClearOfOSMesa || !dladdr(glClearOfGL, &inGL) ||
      !dladdr(glClearOfOSMesa, &inOSMesa)) {
    fprintf(stderr, "FAIL: glClear not found in both libraries\n");
    return 0;
  }
  char fileOfGL[PATH_MAX], fileOfOSMesa[PATH_MAX];
  if (!realpath(inGL.dli_fname, fileOfGL) || !realpath(inOSMesa.dli_fname, fileOfOSMesa)) {
    fprintf(stderr, "FAIL: the files of glClear are not found\n");
    return 0;
  }
  printf("glClear: libGL.so.1's %p in %s, libOSMesa.so.8's %p in %s, the program's %p\n", glClearOfGL,
         fileOfGL, glClearOfOSMesa, fileOfOSMesa, (void *)&glClear);
  if (glClearOfGL != glClearOfOSMesa || inGL.dli_fbase != inOSMesa.dli_fbase ||
      strcmp(fileOfGL, fileOfOSMesa) != 0 || (void *)&glClear != glClearOfGL) {
    fprintf(stderr, "FAIL: two instances\n");
    return 0;
  }
  return 1;
}

int main(int argc, char **argv) {
  static GLubyte pixels[kWidth * kHeight * 4];
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!context || !OSMesaMakeCurrent(context, pixels, GL_UNSIGNED_BYTE, kWidth, kHeight)) {
    fprintf(stderr, "FAIL: no OSMesa context\n");
    return 1;
  }
  glClearColor(0.0f, 0.0f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat diffuse[] = {1.0f, 0.5f, 0.0f, 1.0f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glBegin(GL_TRIANGLES);
  glNormal3f(0.0f, 0.0f, 1.0f);
  glVertex2f(-0.8f, -0.8f);
  glVertex2f(0.8f, -0.8f);
  glVertex2f(0.0f, 0.8f);
  glEnd();
  glFinish();

  /* Light 0 (white, along +z) on the normal: the diffuse colour plus the
   * global ambient 0.2 times the material's ambient 0.2, (1.04, 0.54, 0.04). */
  const GLubyte *p = pixels + 4 * (kWidth * (kHeight / 2) + kWidth / 2);
  const char *renderer = (const char *)glGetString(GL_RENDERER);
  printf("renderer %s, middle pixel %d %d %d %d\n", renderer ? renderer : "(none)", p[0], p[1], p[2], p[3]);
  if (!(p[0] == 255 && p[1] >= 133 && p[1] <= 143 && p[2] >= 5 && p[2] <= 15 && p[3] == 255)) {
    fprintf(stderr, "FAIL: the middle pixel is not the lit triangle's (255 138 10 255)\n");
    return 1;
  }
  if (argc > 1 && strcmp(argv[1], "--one-instance") == 0 && !checkOneInstance()) return 1;
  OSMesaDestroyContext(context);
  printf("PASS\n");
  return 0;
}
