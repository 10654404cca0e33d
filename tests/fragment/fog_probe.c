/* Fog facts on Mesa (llvmpipe), not built: gcc -O1 fog_probe.c -lOSMesa -lm && ./a.out
 * (reference/MESA_FACTS.md, "Fog"). Black quads, white fog, 64x64. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <math.h>
#include <string.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glext.h>
static unsigned char buf[64*64*4];
static void quad(float zl, float zr) {
  glBegin(GL_QUADS);
  glVertex3f(-1,-1,zl); glVertex3f(1,-1,zr); glVertex3f(1,1,zr); glVertex3f(-1,1,zl);
  glEnd();
}
int main(void) {
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64);
  glMatrixMode(GL_PROJECTION); glOrtho(-1,1,-1,1,0,100); glMatrixMode(GL_MODELVIEW);
  glEnable(GL_FOG); float white[4]={1,1,1,1}; glFogfv(GL_FOG_COLOR, white);
  glColor3f(0,0,0);
  /* 1: linear, flat quad at z=-10: |z| constant; radial varies with x, y */
  glFogi(GL_FOG_MODE, GL_LINEAR); glFogf(GL_FOG_START, 0); glFogf(GL_FOG_END, 20);
  glClear(GL_COLOR_BUFFER_BIT); quad(-10,-10); glFinish();
  printf("linear z10: corner %d centre %d\n", buf[0], buf[4*(32*64+32)]);
  /* 2: exp, tilted quad z -2..-18: per fragment vs per vertex */
  glFogi(GL_FOG_MODE, GL_EXP); glFogf(GL_FOG_DENSITY, 0.15f);
  glClear(GL_COLOR_BUFFER_BIT); quad(-2,-18); glFinish();
  printf("exp tilted: centre x=31,32: %d %d (per-fragment ~198, per-vertex ~152)\n", buf[4*(32*64+31)], buf[4*(32*64+32)]);
  /* 3: fog coordinate source with glFogCoordf */
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD); glFogi(GL_FOG_MODE, GL_LINEAR);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glFogCoordf(5); glVertex3f(-1,-1,-10); glVertex3f(1,-1,-10); glVertex3f(1,1,-10); glVertex3f(-1,1,-10);
  glEnd(); glFinish();
  printf("fogcoord 5 linear 0..20: %d (0.25*255=63.75)\n", buf[4*(32*64+32)]);
  /* 4: negative fog coordinate (no abs for GL_FOG_COORD) */
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glFogCoordf(-5); glVertex3f(-1,-1,-10); glVertex3f(1,-1,-10); glVertex3f(1,1,-10); glVertex3f(-1,1,-10);
  glEnd(); glFinish();
  printf("fogcoord -5: %d\n", buf[4*(32*64+32)]);
  printf("ext: %s\n", strstr((const char*)glGetString(GL_EXTENSIONS), "GL_NV_fog_distance") ? "NV_fog_distance" : "no NV_fog_distance");
  return 0;
}
