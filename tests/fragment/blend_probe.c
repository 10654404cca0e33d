/* Blending on Mesa (OSMesa, llvmpipe): 64x64 random source bytes (points, glColor4ubv)
 * over random destination bytes (glDrawPixels), for every factor pair ("pairs"),
 * every equation ("eq") or random separate states ("rand"); each result compared
 * with candidate rules (2 product roundings x lerp or not for complementary pairs),
 * printing the mismatches of each (MESA_FACTS.md, "Blending"). Build:
 *   gcc -O1 blend_probe.c -lOSMesa -lm; usage: ./a.out R G B A pairs|eq|rand */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
enum { N = 64 };
static unsigned long long rs = 1;
static unsigned rnd(void) { rs = rs * 6364136223846793005ull + 1442695040888963407ull; return (unsigned)(rs >> 33); }
static unsigned char src[N*N][4], dst[N*N][4], out[N*N][4];
static unsigned char buf[N*N*4];
static const GLenum F[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_COLOR,
  GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
  GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
static const int PF[] = {0x11, 1, 2, 0x12, 5, 0x15, 3, 0x13, 4, 0x14, 7, 0x17, 8, 0x18, 6};
static const GLenum E[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
static int cst[4];
static int mulv;
static int mul(int a, int b) { int t = a*b; if (mulv==0) return (t + (t>>8) + 128) >> 8; t += 128; return (t + (t >> 8)) >> 8; }
static int lerpv;
static int lerp(int w, int v0, int v1) {
  int wp = w + (w >> 7), d = v1 - v0;
  if (lerpv == 0) { return (v0 + ((wp*d) >> 8)) & 255; }
  if (lerpv == 1) { unsigned m = (unsigned)(wp*d) & 0xffff; unsigned odd = (m & 0x100) >> 8; m = (m + 0x7f + odd) & 0xffff; m >>= 8; return (v0 + m) & 255; }
  return (v0 + ((wp*d*128 + 16384) >> 15)) & 255;
}
static int factor(int f, int k, const unsigned char *s, const unsigned char *d, int alpha) {
  switch (f) {
  case 0: return 0; case 1: return 255; case 2: return s[k]; case 3: return 255 - s[k];
  case 4: return d[k]; case 5: return 255 - d[k]; case 6: return s[3]; case 7: return 255 - s[3];
  case 8: return d[3]; case 9: return 255 - d[3]; case 10: return cst[k]; case 11: return 255 - cst[k];
  case 12: return cst[3]; case 13: return 255 - cst[3];
  case 14: if (alpha) return 255; { int a = s[3], b = 255 - d[3]; return a < b ? a : b; }
  }
  return 0;
}
static int sat(int v) { return v < 0 ? 0 : v > 255 ? 255 : v; }
/* model: lerp path for complementary pairs if lerpOn, both groups same factors */
static int model(int sr, int dr, int sa, int da, int er, int ea, int lerpOn, const unsigned char *s, const unsigned char *d, int k) {
  int alpha = k == 3;
  int sf = alpha ? sa : sr, df = alpha ? da : dr, e = alpha ? ea : er;
  if (E[e] == GL_MIN) return s[k] < d[k] ? s[k] : d[k];
  if (E[e] == GL_MAX) return s[k] > d[k] ? s[k] : d[k];
  int same = (sr == sa && dr == da);
  if (lerpOn && same && E[e] == GL_FUNC_ADD && PF[df] == (PF[sf] ^ 0x10)) {
    if (PF[sf] < PF[df]) return lerp(factor(sf, k, s, d, alpha), d[k], s[k]);
    return lerp(factor(df, k, s, d, alpha), s[k], d[k]);
  }
  int a = mul(s[k], factor(sf, k, s, d, alpha)), b = mul(d[k], factor(df, k, s, d, alpha));
  switch (E[e]) { case GL_FUNC_ADD: return sat(a + b); case GL_FUNC_SUBTRACT: return sat(a - b); default: return sat(b - a); }
}
static void run(int sr, int dr, int sa, int da, int er, int ea) {
  for (int i = 0; i < N*N; ++i) for (int k = 0; k < 4; ++k) { dst[i][k] = rnd() & 255; src[i][k] = rnd() & 255; }
  /* some edge values */
  for (int i = 0; i < N*N; i += 7) { src[i][3] = (i & 8) ? 255 : 0; }
  glDisable(GL_BLEND);
  glRasterPos2i(0, 0);
  glDrawPixels(N, N, GL_RGBA, GL_UNSIGNED_BYTE, dst);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(F[sr], F[dr], F[sa], F[da]);
  glBlendEquationSeparate(E[er], E[ea]);
  glBegin(GL_POINTS);
  for (int i = 0; i < N*N; ++i) { glColor4ubv(src[i]); glVertex2f(i % N + 0.5f, i / N + 0.5f); }
  glEnd();
  glReadPixels(0, 0, N, N, GL_RGBA, GL_UNSIGNED_BYTE, out);
  int best = -1, bestc = 1 << 30, counts[12];
  for (int v = 0; v < 12; ++v) {
    mulv = v & 1; lerpv = (v >> 1) % 3; int lerpOn = v < 6;
    int c = 0;
    for (int i = 0; i < N*N; ++i) for (int k = 0; k < 4; ++k) if (model(sr, dr, sa, da, er, ea, lerpOn, src[i], dst[i], k) != out[i][k]) ++c;
    counts[v] = c; if (c < bestc) { bestc = c; best = v; }
  }
  printf("%2d %2d %2d %2d %d %d best %2d:", sr, dr, sa, da, er, ea, best);
  for (int v = 0; v < 12; ++v) printf(" %d", counts[v]);
  printf("\n");
}
int main(int argc, char **argv) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  if (!OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, N, N)) return 1;
  glMatrixMode(GL_PROJECTION); glLoadIdentity(); glOrtho(0, N, 0, N, -1, 1);
  glMatrixMode(GL_MODELVIEW); glLoadIdentity();
  float bc[4] = {0.3f, 0.5f, 0.7f, 0.1f};
  if (argc > 1) for (int k = 0; k < 4; ++k) bc[k] = atof(argv[1 + k]);
  glBlendColor(bc[0], bc[1], bc[2], bc[3]);
  for (int k = 0; k < 4; ++k) { float f = bc[k] < 0 ? 0 : bc[k] > 1 ? 1 : bc[k]; cst[k] = (int)__builtin_rintf(f * 255.0f); }
  printf("const %d %d %d %d\n", cst[0], cst[1], cst[2], cst[3]);
  const char *mode = argc > 5 ? argv[5] : "pairs";
  if (!strcmp(mode, "pairs")) {
    for (int s = 0; s < 15; ++s) for (int d = 0; d < 14; ++d) run(s, d, s, d, 0, 0);
  } else if (!strcmp(mode, "eq")) {
    for (int e = 0; e < 5; ++e) for (int s = 0; s < 15; ++s) for (int d = 0; d < 14; d += 3) run(s, d, s, d, e, e);
  } else {
    for (int t = 0; t < 300; ++t) run(rnd() % 15, rnd() % 14, rnd() % 15, rnd() % 14, rnd() % 5, rnd() % 5);
  }
  printf("err %x\n", glGetError());
  return 0;
}
