/* The logic op on Mesa (OSMesa, llvmpipe): all 16 ops on random source and
 * destination bytes, with blending off and on (the op must win), and
 * GL_INDEX_LOGIC_OP (no effect in RGBA); prints the mismatches against the
 * bitwise rule (MESA_FACTS.md, "Blending"). Build: gcc logic_op_probe.c -lOSMesa */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
enum { N = 32 };
static unsigned long long rs = 1;
static unsigned rnd(void) { rs = rs * 6364136223846793005ull + 1442695040888963407ull; return (unsigned)(rs >> 33); }
static unsigned char src[N*N][4], dst[N*N][4], out[N*N][4], buf[N*N*4];
static int op(int o, int s, int d) {
  int r;
  switch (o) { case 0: r = 0; break; case 1: r = s & d; break; case 2: r = s & ~d; break; case 3: r = s; break;
  case 4: r = ~s & d; break; case 5: r = d; break; case 6: r = s ^ d; break; case 7: r = s | d; break;
  case 8: r = ~(s | d); break; case 9: r = ~(s ^ d); break; case 10: r = ~d; break; case 11: r = s | ~d; break;
  case 12: r = ~s; break; case 13: r = ~s | d; break; case 14: r = ~(s & d); break; default: r = 255; }
  return r & 255;
}
static int run(int o, int blend, GLenum cap) {
  for (int i = 0; i < N*N; ++i) for (int k = 0; k < 4; ++k) { dst[i][k] = rnd(); src[i][k] = rnd(); }
  glDisable(GL_BLEND); glDisable(GL_COLOR_LOGIC_OP); glDisable(GL_INDEX_LOGIC_OP);
  glRasterPos2i(0, 0); glDrawPixels(N, N, GL_RGBA, GL_UNSIGNED_BYTE, dst);
  if (blend) { glEnable(GL_BLEND); glBlendFunc(GL_SRC_ALPHA, GL_ONE); }
  glEnable(cap); glLogicOp(GL_CLEAR + o);
  glBegin(GL_POINTS);
  for (int i = 0; i < N*N; ++i) { glColor4ubv(src[i]); glVertex2f(i % N + 0.5f, i / N + 0.5f); }
  glEnd();
  glReadPixels(0, 0, N, N, GL_RGBA, GL_UNSIGNED_BYTE, out);
  int bad = 0, copy = 0;
  for (int i = 0; i < N*N; ++i) for (int k = 0; k < 4; ++k) { bad += op(o, src[i][k], dst[i][k]) != out[i][k]; copy += src[i][k] != out[i][k]; }
  printf("op %2d blend %d cap %x: mismatches %d (differs from src: %d)\n", o, blend, cap, bad, copy);
  return bad;
}
int main(void) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, N, N);
  glMatrixMode(GL_PROJECTION); glOrtho(0, N, 0, N, -1, 1);
  for (int o = 0; o < 16; ++o) { run(o, 0, GL_COLOR_LOGIC_OP); run(o, 1, GL_COLOR_LOGIC_OP); }
  run(6, 0, GL_INDEX_LOGIC_OP);
  glDisable(GL_DITHER); printf("err %x\n", glGetError());
  return 0;
}
