// Out-of-range and NaN arguments that once reached undefined behaviour (signed
// overflow, NaN cast to an integer): each is clamped or rounded as Mesa does,
// so the same values come back from the queries as on Mesa.
#include <climits>
#include <cmath>
#include <limits>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using BadInputTest = GLTest;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

// Mesa clamps the viewport origin to GL_VIEWPORT_BOUNDS_RANGE, [-32768, 32767],
// and the size to GL_MAX_VIEWPORT_DIMS.
TEST_F(BadInputTest, ViewportOriginIsClampedToTheBoundsRange) {
  glViewport(INT_MAX, INT_MAX, 10, 10);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ((GetInts<4>(GL_VIEWPORT)), (std::array<GLint, 4>{32767, 32767, 10, 10}));
  glViewport(INT_MIN, -40000, 20000, 5);
  EXPECT_EQ((GetInts<4>(GL_VIEWPORT)), (std::array<GLint, 4>{-32768, -32768, 16384, 5}));
  glViewport(-32768, 32767, 1, 1);
  EXPECT_EQ((GetInts<4>(GL_VIEWPORT)), (std::array<GLint, 4>{-32768, 32767, 1, 1}));
  EXPECT_NO_GL_ERROR();
}

// Drawing with the viewport far outside the window covers nothing and is no
// error (the scissor to the viewport once overflowed here).
TEST_F(BadInputTest, DrawingWithAViewportFarAwayCoversNothing) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(INT_MAX, INT_MAX, 10, 10);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 1, 1);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < kWidth * kHeight * 4; ++i) ASSERT_EQ(pixels()[i], 0) << "byte " << i;
}

// x + col and y + row would pass INT_MAX: no error, nothing read outside the
// framebuffer (the values of pixels outside the window are undefined, §4.3.2;
// Mesa writes zeros there), and a window pixel still reads right.
TEST_F(BadInputTest, ReadPixelsNearIntMax) {
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  std::vector<unsigned char> out(16 * 4, 0x3C);
  glReadPixels(INT_MAX - 2, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glReadPixels(0, INT_MAX - 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glReadPixels(INT_MAX - 2, INT_MAX - 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glReadPixels(INT_MIN, INT_MIN, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glReadPixels(INT_MIN, 0, INT_MAX, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_NO_GL_ERROR();
  unsigned char p[4] = {0, 0, 0, 0};
  glReadPixels(kWidth - 1, kHeight - 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[3], 255);
}

// Mesa's CLAMP turns NaN into 0.
TEST_F(BadInputTest, ClearDepthNaNClearsToZero) {
  glClearDepth(kNaN);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetFloat(GL_DEPTH_CLEAR_VALUE), 0.0f);
  glClear(GL_DEPTH_BUFFER_BIT);
  GLuint d = 12345;
  glReadPixels(3, 3, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &d);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(d, 0u);
}

TEST_F(BadInputTest, ClearColorNaNIsZero) {
  glClearColor(kNaN, 0.5f, kNaN, 1);
  EXPECT_EQ((GetFloats<4>(GL_COLOR_CLEAR_VALUE)), (std::array<GLfloat, 4>{0, 0.5f, 0, 1}));
  glClear(GL_COLOR_BUFFER_BIT);
  const unsigned char* p = pixels();
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 128);
  EXPECT_EQ(p[2], 0);
  EXPECT_EQ(p[3], 255);
}

// glDepthRange(NaN, 1) is (0, 1): a triangle at z = 0 still draws.
TEST_F(BadInputTest, DepthRangeNaNIsZero) {
  glDepthRange(kNaN, 1);
  EXPECT_EQ((GetFloats<2>(GL_DEPTH_RANGE)), (std::array<GLfloat, 2>{0, 1}));
  glDepthRange(0, kNaN);
  EXPECT_EQ((GetFloats<2>(GL_DEPTH_RANGE)), (std::array<GLfloat, 2>{0, 0}));
  glDepthRange(kNaN, 1);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  EXPECT_NO_GL_ERROR();
  const unsigned char* p = pixels() + 4 * (kWidth * (kHeight / 2) + kWidth / 2);
  EXPECT_EQ(p[0], 255);
  GLuint d = 0;
  glReadPixels(kWidth / 2, kHeight / 2, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &d);
  EXPECT_NEAR(static_cast<double>(d), 2147483648.0, 512.0);  // z = 0.5 in [0, 1]
}

// Mesa rounds glPixelStoref's value with lroundf and keeps the low 32 bits:
// NaN and infinities give 0, 3e9 wraps negative (GL_INVALID_VALUE), halves
// round away from zero.
TEST_F(BadInputTest, PixelStorefRoundsAsMesa) {
  glPixelStoref(GL_PACK_ROW_LENGTH, kNaN);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_PACK_ROW_LENGTH), 0);
  glPixelStoref(GL_PACK_SKIP_ROWS, 2.5f);
  EXPECT_EQ(GetInt(GL_PACK_SKIP_ROWS), 3);
  glPixelStoref(GL_PACK_SKIP_ROWS, std::numeric_limits<float>::infinity());
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_PACK_SKIP_ROWS), 0);
  glPixelStoref(GL_UNPACK_ROW_LENGTH, 7);
  glPixelStoref(GL_UNPACK_ROW_LENGTH, 3e9f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_UNPACK_ROW_LENGTH), 7);
  glPixelStoref(GL_PACK_ALIGNMENT, kNaN);  // 0 is no alignment
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 4);
  glPixelStoref(GL_PACK_ALIGNMENT, 1.5f);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 2);
  glPixelStoref(GL_PACK_ALIGNMENT, 0.49999997f);  // lroundf: 0, not 1
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

}  // namespace
}  // namespace glfx_test
