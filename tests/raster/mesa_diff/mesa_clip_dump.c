/* mesa_clip_dump: renders a clip-space scene (see README.md) with Mesa's
 * OSMesa (llvmpipe) and writes the colour and depth buffers of every `dump`.
 * Identity matrices, so glVertex4f gives clip coordinates exactly; colours
 * come from glColor (or, under `twoside 1`, from emission-only two-sided
 * lighting with per-vertex glMaterial).
 * usage: mesa_clip_dump scene.txt out.bin */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float rf(FILE *f) { char b[64]; if (fscanf(f, "%63s", b) != 1) { fprintf(stderr, "eof\n"); exit(1); } return strtof(b, NULL); }
static int ri(FILE *f) { int v; if (fscanf(f, "%i", &v) != 1) { fprintf(stderr, "eof int\n"); exit(1); } return v; }

int main(int argc, char **argv) {
  if (argc != 3) { fprintf(stderr, "usage: mesa_clip_dump scene.txt out.bin\n"); return 2; }
  FILE *f = fopen(argv[1], "r");
  if (!f) { perror(argv[1]); return 2; }
  char cmd[64];
  int W = 0, H = 0, depthBits = 24;
  OSMesaContext ctx = NULL;
  unsigned char *buf = NULL;
  int twoside = 0, constcolor = 0;
  FILE *out = fopen(argv[2], "wb");
  if (!out) { perror(argv[2]); return 2; }
  while (fscanf(f, "%63s", cmd) == 1) {
    if (!strcmp(cmd, "fb")) {
      W = ri(f); H = ri(f); depthBits = ri(f);
      ctx = OSMesaCreateContextExt(OSMESA_RGBA, depthBits, 0, 0, NULL);
      buf = calloc((size_t)W * H, 4);
      if (!OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) { fprintf(stderr, "makecurrent\n"); return 1; }
      glMatrixMode(GL_PROJECTION); glLoadIdentity();
      glMatrixMode(GL_MODELVIEW); glLoadIdentity();
    } else if (!strcmp(cmd, "clear")) {
      float r = rf(f), g = rf(f), b = rf(f), a = rf(f), d = rf(f);
      glClearColor(r, g, b, a); glClearDepth(d);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    } else if (!strcmp(cmd, "shade")) {
      glShadeModel(ri(f) ? GL_FLAT : GL_SMOOTH);
    } else if (!strcmp(cmd, "provoking")) {
      glProvokingVertex(ri(f) ? GL_FIRST_VERTEX_CONVENTION : GL_LAST_VERTEX_CONVENTION);
    } else if (!strcmp(cmd, "cull")) {
      int en = ri(f), mode = ri(f), front = ri(f);
      if (en) glEnable(GL_CULL_FACE); else glDisable(GL_CULL_FACE);
      glCullFace(mode); glFrontFace(front);
    } else if (!strcmp(cmd, "depth")) {
      int en = ri(f), func = ri(f), mask = ri(f);
      if (en) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
      glDepthFunc(func); glDepthMask(mask);
    } else if (!strcmp(cmd, "viewport")) {
      int x = ri(f), y = ri(f), w = ri(f), h = ri(f);
      glViewport(x, y, w, h);
    } else if (!strcmp(cmd, "range")) {
      double n = rf(f), fa = rf(f);
      glDepthRange(n, fa);
    } else if (!strcmp(cmd, "offset")) {
      /* polygon offset: the three enables, factor, units */
      int fill = ri(f), line = ri(f), point = ri(f);
      float factor = rf(f), units = rf(f);
      if (fill) glEnable(GL_POLYGON_OFFSET_FILL); else glDisable(GL_POLYGON_OFFSET_FILL);
      if (line) glEnable(GL_POLYGON_OFFSET_LINE); else glDisable(GL_POLYGON_OFFSET_LINE);
      if (point) glEnable(GL_POLYGON_OFFSET_POINT); else glDisable(GL_POLYGON_OFFSET_POINT);
      glPolygonOffset(factor, units);
    } else if (!strcmp(cmd, "stipple")) {
      /* polygon stipple: enable, and a pattern made from a seed */
      int en = ri(f);
      unsigned seed = (unsigned)ri(f);
      GLubyte p[128];
      for (int i = 0; i < 128; i++) { seed = seed * 1103515245u + 12345u; p[i] = (GLubyte)(seed >> 16); }
      glPolygonStipple(p);
      if (en) glEnable(GL_POLYGON_STIPPLE); else glDisable(GL_POLYGON_STIPPLE);
    } else if (!strcmp(cmd, "polymode")) {
      int front = ri(f), back = ri(f);
      glPolygonMode(GL_FRONT, front);
      glPolygonMode(GL_BACK, back);
    } else if (!strcmp(cmd, "smooth")) {
      /* GL_POINT_SMOOTH and GL_LINE_SMOOTH: they change how llvmpipe draws polygons too */
      int pt = ri(f), ln = ri(f);
      if (pt) glEnable(GL_POINT_SMOOTH); else glDisable(GL_POINT_SMOOTH);
      if (ln) glEnable(GL_LINE_SMOOTH); else glDisable(GL_LINE_SMOOTH);
    } else if (!strcmp(cmd, "colorsum")) {
      if (ri(f)) glEnable(GL_COLOR_SUM); else glDisable(GL_COLOR_SUM);
    } else if (!strcmp(cmd, "constcolor")) {
      /* colours given once, before glBegin, after a flush: Mesa then reads
       * them as constants (see primitive.h, constantPrimary) */
      constcolor = ri(f);
    } else if (!strcmp(cmd, "twoside")) {
      twoside = ri(f);
      if (twoside) {
        static const float zero[4] = {0, 0, 0, 0};
        glEnable(GL_LIGHTING);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
        glDisable(GL_LIGHT0);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
      } else {
        glDisable(GL_LIGHTING);
      }
    } else if (!strcmp(cmd, "begin")) {
      int mode = ri(f), n = ri(f);
      if (constcolor) {
        /* a flush (a real state change), then the colours, then glBegin */
        GLint sm; glGetIntegerv(GL_SHADE_MODEL, &sm);
        glShadeModel(sm == GL_FLAT ? GL_SMOOTH : GL_FLAT); glShadeModel(sm);
      }
      for (int i = 0; i < n; i++) {
        float p[4], c[4], s[3], b[4];
        for (int k = 0; k < 4; k++) p[k] = rf(f);
        for (int k = 0; k < 4; k++) c[k] = rf(f);
        for (int k = 0; k < 3; k++) s[k] = rf(f);
        for (int k = 0; k < 4; k++) b[k] = rf(f);
        if (i == 0) {
          if (constcolor && !twoside) { glColor4fv(c); glSecondaryColor3fv(s); }
          glBegin(mode);
        }
        if (twoside) {
          float fd[4] = {0, 0, 0, c[3]}, bd[4] = {0, 0, 0, b[3]};
          glMaterialfv(GL_FRONT, GL_EMISSION, c);
          glMaterialfv(GL_FRONT, GL_DIFFUSE, fd);
          glMaterialfv(GL_BACK, GL_EMISSION, b);
          glMaterialfv(GL_BACK, GL_DIFFUSE, bd);
        } else if (!constcolor) {
          glColor4fv(c);
        }
        if (!constcolor) glSecondaryColor3fv(s);
        glVertex4fv(p);
      }
      glEnd();
    } else if (!strcmp(cmd, "dump")) {
      glFinish();
      fwrite(&W, 4, 1, out); fwrite(&H, 4, 1, out);
      fwrite(buf, 4, (size_t)W * H, out);
      GLint dw, dh, bpv; void *dp;
      if (depthBits && OSMesaGetDepthBuffer(ctx, &dw, &dh, &bpv, &dp)) {
        for (int y = 0; y < H; y++)
          for (int x = 0; x < W; x++) {
            unsigned v = bpv == 2 ? ((unsigned short *)dp)[y * dw + x] : ((unsigned *)dp)[y * dw + x];
            fwrite(&v, 4, 1, out);
          }
      } else {
        unsigned z = 0;
        for (int i = 0; i < W * H; i++) fwrite(&z, 4, 1, out);
      }
    } else {
      fprintf(stderr, "unknown command %s\n", cmd); return 1;
    }
  }
  fclose(out);
  return 0;
}
