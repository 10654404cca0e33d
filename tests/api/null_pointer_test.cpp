// Null arrays handed to the v-forms and queries: the library's edge must not
// crash on them (Mesa does); the call does nothing and the state stays as it
// was. libglfixed only: not run against Mesa.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

#ifndef TESTING_AGAINST_MESA
using NullPointerTest = GLTest;

TEST_F(NullPointerTest, VertexAttributeArraysAreIgnored) {
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glNormal3f(0, 1, 0);
  glBegin(GL_TRIANGLES);
  glVertex3fv(nullptr);
  glVertex2dv(nullptr);
  glColor3fv(nullptr);
  glColor4ubv(nullptr);
  glNormal3fv(nullptr);
  glTexCoord2fv(nullptr);
  glMultiTexCoord2fv(GL_TEXTURE0, nullptr);
  glSecondaryColor3fv(nullptr);
  glFogCoordfv(nullptr);
  glIndexiv(nullptr);
  glEdgeFlagv(nullptr);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, nullptr);
  glEnd();
  GLfloat c[4], n[3];
  glGetFloatv(GL_CURRENT_COLOR, c);
  glGetFloatv(GL_CURRENT_NORMAL, n);
  EXPECT_FLOAT_EQ(c[0], 0.25f);
  EXPECT_FLOAT_EQ(c[2], 0.75f);
  EXPECT_FLOAT_EQ(n[1], 1.0f);
}

TEST_F(NullPointerTest, StateArraysAndQueriesAreIgnored) {
  glLoadMatrixf(nullptr);
  glMultMatrixd(nullptr);
  glLightfv(GL_LIGHT0, GL_POSITION, nullptr);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, nullptr);
  glMaterialiv(GL_FRONT, GL_AMBIENT, nullptr);
  glGetFloatv(GL_MODELVIEW_MATRIX, nullptr);
  glGetIntegerv(GL_VIEWPORT, nullptr);
  glGetLightfv(GL_LIGHT0, GL_DIFFUSE, nullptr);
  glGetMaterialiv(GL_FRONT, GL_DIFFUSE, nullptr);
  glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLfloat m[16], light[4];
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  glGetLightfv(GL_LIGHT0, GL_POSITION, light);
  EXPECT_FLOAT_EQ(m[0], 1.0f);
  EXPECT_FLOAT_EQ(light[2], 1.0f);  // the default (0, 0, 1, 0)
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
#endif

}  // namespace
}  // namespace glfx_test
