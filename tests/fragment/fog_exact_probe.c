/* Fog bit for bit on Mesa (llvmpipe), not built:
 *   gcc -O2 -ffp-contract=off fog_exact_probe.c -lOSMesa -lm && ./a.out MODE DENSITY START END [SCALE]
 * MODE 0 linear, 1 GL_EXP, 2 GL_EXP2 (reference/MESA_FACTS.md, "Fog").
 * One GL_POINT a pixel (256 x 256) with its own fog coordinate, white
 * points in black fog on a FLOAT colour buffer: the red channel is the fog
 * factor f exactly as the shader computed it. Each candidate rule is
 * compared with every pixel; the rules kept in fragment/fog.inc miss none. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#define W 256
static float buf[W * W * 4];

static const double C[6] = {1.0, 0.693153073200168932794, 0.240153617044375388211, 0.0558263180532956664775,
                            0.00898934009049466391101, 0.00187757667519147912699};
static float mad(float a, float b, float c, int fused) { return fused ? fmaf(a, b, c) : a * b + c; }
/* variant bit 0: fused multiply-adds; bit 1: Horner instead of even / odd halves */
static float exp2Candidate(float x, int variant) {
  x = x > 128.0f ? 128.0f : x;
  x = x < -126.99999f ? -126.99999f : x;
  const float whole = floorf(x), fp = x - whole;
  const int fused = variant & 1;
  float p;
  if (variant & 2) {
    p = (float)C[5];
    for (int i = 4; i >= 0; --i) p = mad(fp, p, (float)C[i], fused);
  } else {
    const float x2 = fp * fp;
    const float odd = mad(x2, mad(x2, (float)C[5], (float)C[3], fused), (float)C[1], fused);
    const float even = mad(x2, mad(x2, (float)C[4], (float)C[2], fused), (float)C[0], fused);
    p = mad(odd, fp, even, fused);
  }
  union { int i; float f; } u;
  u.i = ((int)whole + 127) << 23;
  return u.f * p;
}
static float sat(float f) { f = f > 0 ? f : 0; return f < 1 ? f : 1; }

int main(int argc, char **argv) {
  if (argc < 5) return 1;
  const int mode = atoi(argv[1]);
  const float density = atof(argv[2]), start = atof(argv[3]), end = atof(argv[4]);
  const float step = argc > 5 && atoi(argv[5]) ? 0.01f : 0.0003f;
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  OSMesaMakeCurrent(c, buf, GL_FLOAT, W, W);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, W, 0, W, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_FOG);
  const float black[4] = {0, 0, 0, 0};
  glFogfv(GL_FOG_COLOR, black);
  const GLenum modes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
  glFogi(GL_FOG_MODE, modes[mode]);
  glFogf(GL_FOG_DENSITY, density);
  glFogf(GL_FOG_START, start);
  glFogf(GL_FOG_END, end);
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glColor4f(1, 1, 1, 1);
  glBegin(GL_POINTS);
  for (int i = 0; i < W * W; ++i) {
    glFogCoordf(i * step);
    glVertex2f(i % W + 0.5f, i / W + 0.5f);
  }
  glEnd();
  glFinish();
  if (mode == 0) {
    const float s = end == start ? 1.0f : -1.0f / (end - start), o = end * -s;
    int unfused = 0, fused = 0;
    for (int i = 0; i < W * W; ++i) {
      const float cf = i * step;
      unfused += sat(cf * s + o) != buf[4 * i];
      fused += sat(fmaf(cf, s, o)) != buf[4 * i];
    }
    printf("linear: unfused %d, fused %d mismatches\n", unfused, fused);
    return 0;
  }
  const float d = (float)(density * (mode == 1 ? M_LOG2E : 1.201122408786449815));
  for (int variant = 0; variant < 4; ++variant) {
    int bad = 0;
    for (int i = 0; i < W * W; ++i) {
      const float cf = i * step, t = cf * d;
      const float f = sat(exp2Candidate(mode == 1 ? -t : -(t * t), variant));
      bad += f != buf[4 * i];
    }
    printf("%s, %s: %d mismatches\n", variant & 1 ? "fused" : "unfused", variant & 2 ? "Horner" : "even/odd", bad);
  }
  return 0;
}
