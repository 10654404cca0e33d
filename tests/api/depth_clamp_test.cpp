// ARB_depth_clamp (GL 3.2 §2.17): GL_DEPTH_CLAMP turns off the near and far
// clip planes and clamps fragment depth to the depth range. The depth values
// below were measured on Mesa 22.3 (the test runs there too).
#include "api/gl_test_fixture.h"

#ifndef GL_DEPTH_CLAMP
#define GL_DEPTH_CLAMP 0x864F
#endif

namespace glfx_test {
namespace {

using DepthClampTest = GLTest;

TEST_F(DepthClampTest, IsAnEnableInTheTransformAndEnableGroups) {
  EXPECT_EQ(glIsEnabled(GL_DEPTH_CLAMP), GL_FALSE);
  glEnable(GL_DEPTH_CLAMP);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_CLAMP), GL_TRUE);
  EXPECT_EQ(GetBool(GL_DEPTH_CLAMP), GL_TRUE);
  for (GLbitfield group : {GL_TRANSFORM_BIT, GL_ENABLE_BIT}) {
    glPushAttrib(group);
    glDisable(GL_DEPTH_CLAMP);
    glPopAttrib();
    EXPECT_EQ(glIsEnabled(GL_DEPTH_CLAMP), GL_TRUE) << group;
  }
  glPushAttrib(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_CLAMP);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_DEPTH_CLAMP), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

// A triangle reaching past both planes, drawn whole, its depth clamped to
// the depth range [0.25, 0.75].
TEST_F(DepthClampTest, DrawsPastNearAndFarWithClampedDepth) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_CLAMP);
  glDepthRange(0.25, 0.75);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, -3);
  glVertex3f(3, -1, 3);
  glVertex3f(-1, 3, 0.5f);
  glEnd();
  std::vector<GLuint> d(kWidth * kHeight);
  glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d.data());
  ASSERT_NO_GL_ERROR();
  unsigned long long sum = 0;
  for (GLuint z : d) sum += z >> 8;
  EXPECT_EQ(d[0] >> 8, 4194304u);  // 0.25
  EXPECT_EQ(d[32 * kWidth + 32] >> 8, 5922816u);
  EXPECT_EQ(d[kWidth * kHeight - 1] >> 8, 12582911u);  // 0.75
  EXPECT_EQ(sum, 27746450262ull);
  // Without the clamp the parts past the planes are clipped away.
  glDisable(GL_DEPTH_CLAMP);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, -3);
  glVertex3f(3, -1, 3);
  glVertex3f(-1, 3, 0.5f);
  glEnd();
  EXPECT_EQ(pixels()[0], 0);  // the corner near z = -3
}

TEST_F(DepthClampTest, RasterPositionPastTheFarPlaneIsValid) {
  glEnable(GL_DEPTH_CLAMP);
  glRasterPos3f(0, 0, 2);
  EXPECT_EQ(GetInt(GL_CURRENT_RASTER_POSITION_VALID), GL_TRUE);
  GLfloat rp[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  EXPECT_FLOAT_EQ(rp[2], 1.5f);  // not clamped
  glRasterPos3f(0, 0, -3);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  EXPECT_FLOAT_EQ(rp[2], -1.0f);
  glDisable(GL_DEPTH_CLAMP);
  glRasterPos3f(0, 0, 2);
  EXPECT_EQ(GetInt(GL_CURRENT_RASTER_POSITION_VALID), GL_FALSE);
  // glDrawPixels from there draws, its depth clamped to 1.
  glEnable(GL_DEPTH_CLAMP);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glRasterPos3f(0, 0, 2);
  const GLubyte white[4 * 4 * 4] = {255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
                                    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255};
  glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, white);
  GLuint z = 0;
  glReadPixels(33, 33, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
  EXPECT_EQ(z >> 8, 16777215u);
  EXPECT_EQ(pixels()[(33 * kWidth + 33) * 4], 255);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
