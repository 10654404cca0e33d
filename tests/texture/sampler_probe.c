/* Draws one textured case on Mesa's OSMesa (llvmpipe) and writes the
 * window's pixels: the reference tests/texture/sampler_test.cpp compares
 * texture::sampleBlock with. Built against the system's libOSMesa by CMake.
 *
 * Input (stdin), native 32-bit words, floats as their bits:
 *   window width, height
 *   target, number of images; per image: image target (a cube face or the
 *     target), level, internal format, width, height, depth, format, type,
 *     byte count, then the bytes padded to a multiple of 4
 *   min filter, mag filter, wrap s, t, r, border colour (4 floats),
 *   lod bias, min lod, max lod (floats), base level, max level,
 *   unit lod bias (float), compare mode, compare func, depth texture mode
 *   number of vertices (triangles); per vertex x, y (window), s, t, r, q (floats)
 * Output (stdout): width * height RGBA bytes, bottom row first.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned word(void) {
  unsigned w;
  if (fread(&w, 4, 1, stdin) != 1) {
    fprintf(stderr, "sampler_probe: short input\n");
    exit(2);
  }
  return w;
}
static float fword(void) {
  unsigned w = word();
  float f;
  memcpy(&f, &w, 4);
  return f;
}

int main(void) {
  int width = (int)word(), height = (int)word();
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  unsigned char* pixels = calloc((size_t)width * height, 4);
  if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, width, height)) return 3;
  GLenum target = word();
  GLuint tex;
  glGenTextures(1, &tex);
  glBindTexture(target, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  unsigned images = word();
  for (unsigned i = 0; i < images; ++i) {
    GLenum imageTarget = word();
    int level = (int)word(), internalFormat = (int)word();
    int w = (int)word(), h = (int)word(), d = (int)word();
    GLenum format = word(), type = word();
    unsigned bytes = word();
    unsigned char* data = malloc(bytes + 4);
    if (fread(data, 1, (bytes + 3) & ~3u, stdin) != ((bytes + 3) & ~3u)) return 2;
    if (target == GL_TEXTURE_1D)
      glTexImage1D(imageTarget, level, internalFormat, w, 0, format, type, data);
    else if (target == GL_TEXTURE_3D)
      glTexImage3D(imageTarget, level, internalFormat, w, h, d, 0, format, type, data);
    else
      glTexImage2D(imageTarget, level, internalFormat, w, h, 0, format, type, data);
    free(data);
  }
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)word());
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)word());
  glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)word());
  glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)word());
  glTexParameteri(target, GL_TEXTURE_WRAP_R, (GLint)word());
  float border[4];
  for (int i = 0; i < 4; ++i) border[i] = fword();
  glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameterf(target, GL_TEXTURE_LOD_BIAS, fword());
  glTexParameterf(target, GL_TEXTURE_MIN_LOD, fword());
  glTexParameterf(target, GL_TEXTURE_MAX_LOD, fword());
  glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, (GLint)word());
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, (GLint)word());
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, fword());
  glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, (GLint)word());
  glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, (GLint)word());
  glTexParameteri(target, GL_DEPTH_TEXTURE_MODE, (GLint)word());
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(target);

  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, 0, height, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  unsigned vertices = word();
  glBegin(GL_TRIANGLES);
  for (unsigned i = 0; i < vertices; ++i) {
    float x = fword(), y = fword(), s = fword(), t = fword(), r = fword(), q = fword();
    glTexCoord4f(s, t, r, q);
    glVertex2f(x, y);
  }
  glEnd();
  glFinish();
  if (glGetError() != GL_NO_ERROR) return 4;
  fwrite(pixels, 4, (size_t)width * height, stdout);
  OSMesaDestroyContext(ctx);
  free(pixels);
  return 0;
}
