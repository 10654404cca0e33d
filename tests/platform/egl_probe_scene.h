/* The scene and the comparison the EGL probes share (egl_pbuffer_probe.c,
   egl_window_probe.c): a lit, depth-tested triangle over an unlit one, and
   the fidelity bar (no pixel covered on one side only, >= 99.99% identical,
   no channel off by more than 1) over two W x H RGBA pictures, row 0 at the
   bottom. */
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>

enum { W = 64, H = 48 };

static int comparePictures(const char* a, const char* b) {
  static unsigned char pa[W * H * 4], pb[W * H * 4];
  FILE* fa = fopen(a, "rb");
  FILE* fb = fopen(b, "rb");
  if (!fa || !fb || fread(pa, 1, sizeof pa, fa) != sizeof pa || fread(pb, 1, sizeof pb, fb) != sizeof pb) {
    fprintf(stderr, "cannot read %s or %s\n", a, b);
    return 2;
  }
  int covered = 0, coverageMismatch = 0, exact = 0, maxDiff = 0;
  for (int i = 0; i < W * H; ++i) {
    const unsigned char* x = pa + 4 * i;
    const unsigned char* y = pb + 4 * i;
    /* The clear colour is (0, 0, 0, 255): anything else is covered. */
    int cx = x[0] || x[1] || x[2], cy = y[0] || y[1] || y[2];
    if (cx != cy) ++coverageMismatch;
    if (!cx && !cy) continue;
    ++covered;
    int d = 0;
    for (int c = 0; c < 4; ++c) {
      int e = abs(x[c] - y[c]);
      if (e > d) d = e;
    }
    if (d == 0) ++exact;
    if (d > maxDiff) maxDiff = d;
  }
  printf("covered %d, coverage mismatches %d, exact %d, max channel difference %d\n", covered,
         coverageMismatch, exact, maxDiff);
  return covered > 100 && coverageMismatch == 0 && exact * 10000.0 >= covered * 9999.0 && maxDiff <= 1 ? 0
                                                                                                       : 1;
}

/* "flat" shades the lit triangle flat; smooth otherwise. */
static void drawScene(int smooth) {
  /* A lit, depth-tested triangle over a smaller one. */
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const GLfloat lightPos[] = {0.3f, 0.5f, 1.0f, 0.0f};
  const GLfloat diffuse[] = {0.9f, 0.6f, 0.3f, 1.0f};
  /* Every frame the same: the matrices start again, and the light is placed
     under an identity modelview. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.75, 0.75, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glLightfv(GL_LIGHT0, GL_POSITION, lightPos);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
  glTranslatef(0, 0, -3);
  glRotatef(30, 1, 0.5f, 0);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex3f(-1.2f, -1, 0);
  glNormal3f(0.5f, 0, 0.8f);
  glVertex3f(1.2f, -0.8f, 0.2f);
  glNormal3f(0, 0.6f, 0.8f);
  glVertex3f(0, 1.1f, -0.2f);
  glEnd();
  glDisable(GL_LIGHTING);
  glColor3f(0.2f, 0.8f, 0.4f);
  glBegin(GL_TRIANGLES);
  glVertex3f(-0.5f, -0.5f, 0.5f);
  glVertex3f(0.5f, -0.5f, -0.5f);
  glVertex3f(0, 0.5f, 0.3f);
  glEnd();
}
