/* Measures the llvmpipe colours that tests/vertex/lighting_quirks_test.cpp
 * pins. Each case lights one vertex of a flat-shaded triangle covering the
 * 8x8 buffer and prints the pixel.
 *
 *   cc lighting_quirks_probe.c -o lighting_quirks_probe -lOSMesa && ./lighting_quirks_probe
 *
 * (Debian 12, Mesa 22.3.6, llvmpipe.) */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>

static unsigned char buf[8 * 8 * 4];

static void reset(void) {
  float zero[4] = {0, 0, 0, 1}, one[4] = {1, 1, 1, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0);
  glLightfv(GL_LIGHT0, GL_AMBIENT, zero);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, one);
  glLightfv(GL_LIGHT0, GL_SPECULAR, one);
  float dir[4] = {0, 0, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
  glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
  float sd[3] = {0, 0, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, sd);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, zero);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
}

/* One front-facing triangle; its last vertex (the provoking one) at the
 * origin with normal n. */
static void draw(const char* name, float nx, float ny, float nz) {
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex3f(-1, -1, 0);
  glVertex3f(3, -1, 0);
  glNormal3f(nx, ny, nz);
  glVertex3f(0, 0, 0);
  glEnd();
  glFinish();
  const unsigned char* p = &buf[(2 * 8 + 2) * 4];
  printf("%-28s %3d %3d %3d %3d\n", name, p[0], p[1], p[2], p[3]);
}

int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 8, 8);
  glShadeModel(GL_FLAT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  float white[4] = {1, 1, 1, 1};

  /* gallivm's pow: light and half vector (0,0,1), so n.h = n.z exactly;
   * colour = pow(n.z, shininess). Cases where the exact power rounds the
   * other way. */
  static const float pows[][2] = {{0.987513363f, 59},  {0.994659483f, 83},  {0.99561882f, 28},
                                  {0.99681735f, 119},  {0.997174561f, 78},  {0.990554512f, 92},
                                  {0.986421824f, 49},  {0.994244337f, 107}, {0.999715149f, 119},
                                  {0.995298624f, 128}, {0.994674623f, 100}, {0.998495996f, 70}};
  for (int i = 0; i < 12; ++i) {
    reset();
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, pows[i][1]);
    char name[64];
    snprintf(name, sizeof name, "pow %.9g^%g", pows[i][0], pows[i][1]);
    draw(name, 0, 0, pows[i][0]);
  }

  /* Shininess 0 everywhere: full specular where n.L > 0 although n.h < 0. */
  float spec[4] = {0.4f, 0.6f, 0.8f, 1};
  float slanted[4] = {1, 0, 0.05f, 0};
  reset();
  glLightfv(GL_LIGHT0, GL_POSITION, slanted);
  glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  draw("shin0 all zero, n.h<0", 0.3f, 0, -0.9f);
  /* Two-sided with a non-zero back shininess: the front's 0^0 is 0. */
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  glMaterialf(GL_BACK, GL_SHININESS, 10);
  draw("shin0 mixed, n.h<0", 0.3f, 0, -0.9f);
  /* ... and where n.h > 0 it is 1. */
  draw("shin0 mixed, n.h>0", 0.9f, 0, 0.1f);

  /* Shininess 0 everywhere, attenuated local light: (n.L)^(n.L). */
  reset();
  float local[4] = {0, 0, 2, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, local);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.5f);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  draw("shin0 attenuated n.L=0.5", 0, 0, 0.5f);
  draw("shin0 attenuated n.L=0.2", 0, 0, 0.2f);
  /* ... a spot light (no distance attenuation) too. */
  reset();
  glLightfv(GL_LIGHT0, GL_POSITION, local);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60);
  glMaterialfv(GL_FRONT, GL_SPECULAR, white);
  draw("shin0 spot n.L=0.3", 0, 0, 0.3f);

  /* A directional spot light: the cone tests the light's own direction. */
  reset();
  glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 20);
  draw("dir spot inside", 0, 0, 1);
  float away[3] = {0, 0, 1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, away);
  draw("dir spot outside", 0, 0, 1);
  float tilted[3] = {0.3f, 0, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, tilted);
  draw("dir spot tilted", 0, 0, 1);

  /* NaN and infinities clamp to 1, 1, 0. */
  reset();
  float nanEmission[4] = {NAN, INFINITY, -INFINITY, 1};
  glMaterialfv(GL_FRONT, GL_EMISSION, nanEmission);
  float alphaNan[4] = {0, 0, 0, NAN};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, alphaNan);
  draw("nan inf -inf / alpha nan", 0, 0, 1);

  /* Mesa 22.3's red-only back products: two-sided, per-vertex front and back
   * diffuse, back-facing triangle lit from behind. */
  reset();
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  float lightBehind[4] = {0, 0, -1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, lightBehind);
  float fd[4] = {0.2f, 0.4f, 0.6f, 1}, bd[4] = {0.9f, 0.1f, 0.1f, 1}, ba[4] = {0.5f, 0.05f, 0.05f, 1};
  glLightfv(GL_LIGHT0, GL_AMBIENT, white);
  glMaterialfv(GL_BACK, GL_AMBIENT, ba);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, fd);
  glMaterialfv(GL_BACK, GL_DIFFUSE, bd);
  glNormal3f(0, 0, 1);
  glVertex3f(-1, -1, 0);
  glVertex3f(-1, 3, 0);
  glVertex3f(3, -1, 0);
  glEnd();
  glFinish();
  const unsigned char* p = &buf[(2 * 8 + 2) * 4];
  printf("%-28s %3d %3d %3d %3d\n", "back product quirk", p[0], p[1], p[2], p[3]);
  return 0;
}
