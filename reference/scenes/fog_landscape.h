/* Shared by the fog_landscape_* scenes: a lit, smooth-shaded landscape mesh
 * (a height field of sines) receding into the distance under a perspective
 * projection, drawn with fog of a bluish grey in the given mode. */
#include <math.h>
#include "scene.h"

#define FOG_GRID 24

static float fog_height(int i, int j) {
  return 0.8f * sinf(i * 0.55f) * cosf(j * 0.4f) + 0.35f * sinf(i * 0.23f + j * 0.71f);
}

static void fog_landscape(GLenum mode, float density, float start, float end) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 60.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, -1.6f, -2.5f);
  glRotatef(12, 1, 0, 0);
  glClearColor(0.45f, 0.5f, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  const GLfloat sun[4] = {0.3f, 1.0f, 0.4f, 0}, white[4] = {1, 1, 1, 1}, amb[4] = {0.2f, 0.2f, 0.2f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, sun);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);

  const GLfloat fogColor[4] = {0.55f, 0.6f, 0.7f, 1};
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, mode);
  glFogfv(GL_FOG_COLOR, fogColor);
  glFogf(GL_FOG_DENSITY, density);
  glFogf(GL_FOG_START, start);
  glFogf(GL_FOG_END, end);

  const float cell = 1.4f;
  for (int j = 0; j < FOG_GRID; ++j) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= FOG_GRID; ++i) {
      for (int k = 0; k < 2; ++k) {
        const int jj = j + k;
        const float x = (i - FOG_GRID / 2) * cell, z = -jj * cell;
        const float h = fog_height(i, jj);
        const float dx = fog_height(i + 1, jj) - fog_height(i - 1, jj);
        const float dz = fog_height(i, jj + 1) - fog_height(i, jj - 1);
        glNormal3f(-dx / (2 * cell), 1, dz / (2 * cell));
        glColor3f(0.25f + 0.2f * h, 0.55f + 0.15f * h, 0.2f);
        glVertex3f(x, h, z);
      }
    }
    glEnd();
  }
  glDisable(GL_LIGHTING);
  /* A few floating markers at different depths, unlit and flat. */
  glShadeModel(GL_FLAT);
  glBegin(GL_QUADS);
  for (int m = 0; m < 6; ++m) {
    const float z = -3.0f - m * 5.5f, x = (m % 2 ? 1.5f : -1.5f);
    glColor3f(0.9f, 0.2f + 0.1f * m, 0.1f);
    glVertex3f(x - 0.4f, 1.0f, z);
    glVertex3f(x + 0.4f, 1.0f, z);
    glVertex3f(x + 0.4f, 1.8f, z);
    glVertex3f(x - 0.4f, 1.8f, z);
  }
  glEnd();
}
