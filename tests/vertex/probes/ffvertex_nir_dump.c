/* Makes Mesa print the NIR of the fixed-function vertex shader it builds for a
 * lighting state: the exact operations, in order, that llvmpipe runs (dot
 * products summed z first, the attenuation NIR rewrote, LIT, the red-only back
 * products). The lighting stage (libglfixed/vertex/lighting.cpp) follows it.
 *
 *   cc ffvertex_nir_dump.c -o ffvertex_nir_dump -lOSMesa
 *   ST_DEBUG=nir ./ffvertex_nir_dump pos atten spot shin 2>&1 | less
 *     (the last "shader: MESA_SHADER_VERTEX" block is this state's)
 *
 * flags: pos spot atten lv two sep norm resc shin cm bem scale bemshin 2lights
 *        cmdiff cmback cmbackamb cmspec cmfrontad bemback bembackamb bembackspec */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>
static unsigned char buf[16 * 16 * 4];
int main(int argc, char** argv) {
  int pos = 0, spot = 0, atten = 0, lv = 0, two = 0, sep = 0, norm = 0, resc = 0, shin = 0, cm = 0, bem = 0,
      scale = 0, lights = 1, bemshin = 0;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!strcmp(a, "pos")) pos = 1;
    if (!strcmp(a, "spot")) spot = 1;
    if (!strcmp(a, "atten")) atten = 1;
    if (!strcmp(a, "lv")) lv = 1;
    if (!strcmp(a, "two")) two = 1;
    if (!strcmp(a, "sep")) sep = 1;
    if (!strcmp(a, "norm")) norm = 1;
    if (!strcmp(a, "resc")) resc = 1;
    if (!strcmp(a, "shin")) shin = 1;
    if (!strcmp(a, "cm")) cm = 1;
    if (!strcmp(a, "bem")) bem = 1;
    if (!strcmp(a, "scale")) scale = 1;
    if (!strcmp(a, "bemshin")) bemshin = 1;
    if (!strcmp(a, "2lights")) lights = 2;
  }
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16);
  glEnable(GL_LIGHTING);
  for (int l = 0; l < lights; ++l) {
    glEnable(GL_LIGHT0 + l);
    float lp[4] = {0.3f, 0.4f, 1, pos ? 1.0f : 0.0f};
    glLightfv(GL_LIGHT0 + l, GL_POSITION, lp);
    if (spot) glLightf(GL_LIGHT0 + l, GL_SPOT_CUTOFF, 40);
    if (spot) glLightf(GL_LIGHT0 + l, GL_SPOT_EXPONENT, 3);
    if (atten) glLightf(GL_LIGHT0 + l, GL_LINEAR_ATTENUATION, 0.5f);
  }
  if (lv) glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  if (two) glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  if (sep) glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  if (norm) glEnable(GL_NORMALIZE);
  if (resc) glEnable(GL_RESCALE_NORMAL);
  if (shin) glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 10);
  if (cm) glEnable(GL_COLOR_MATERIAL);
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "cmdiff")) {
      glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
      glEnable(GL_COLOR_MATERIAL);
    }
    if (!strcmp(argv[i], "cmback")) {
      glColorMaterial(GL_BACK, GL_DIFFUSE);
      glEnable(GL_COLOR_MATERIAL);
    }
    if (!strcmp(argv[i], "cmbackamb")) {
      glColorMaterial(GL_BACK, GL_AMBIENT);
      glEnable(GL_COLOR_MATERIAL);
    }
    if (!strcmp(argv[i], "cmfrontad")) {
      glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
      glEnable(GL_COLOR_MATERIAL);
    }
    if (!strcmp(argv[i], "cmspec")) {
      glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR);
      glEnable(GL_COLOR_MATERIAL);
    }
  }
  if (scale) {
    glMatrixMode(GL_MODELVIEW);
    glScalef(1, 2, 3);
  }
  float d[4] = {0.5f, 0.5f, 0.5f, 1};
  glBegin(GL_TRIANGLES);
  if (bem) {
    glMaterialfv(GL_FRONT, GL_DIFFUSE, d);
    glMaterialfv(GL_BACK, GL_DIFFUSE, d);
  }
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "bemback")) glMaterialfv(GL_BACK, GL_DIFFUSE, d);
    if (!strcmp(argv[i], "bembackamb")) glMaterialfv(GL_BACK, GL_AMBIENT, d);
    if (!strcmp(argv[i], "bembackspec")) glMaterialfv(GL_BACK, GL_SPECULAR, d);
  }
  if (bemshin) {
    glMaterialf(GL_FRONT, GL_SHININESS, 0);
  }
  glColor3f(1, 0, 0);
  glNormal3f(0, 0, 1);
  glVertex2f(-1, -1);
  glColor3f(0, 1, 0);
  glVertex2f(1, -1);
  glColor3f(0, 0, 1);
  glVertex2f(0, 1);
  glEnd();
  glFinish();
  return 0;
}
