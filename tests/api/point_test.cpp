// Points (GL 2.1 §3.4): glPointSize, glPointParameter*, their queries and
// errors, and the pixels a point covers. Every value here was probed on
// Mesa 22.3.6 (llvmpipe); the test also runs against Mesa.
#define GL_GLEXT_PROTOTYPES 1
#include "gl_test_fixture.h"

#ifndef GL_POINT_SIZE_MIN
#include <GL/glext.h>
#endif

#include <cmath>
#include <limits>

namespace glfx_test {
namespace {

class PointTest : public GLTest {
 protected:
  // One unit one pixel, the buffer cleared to black.
  void SetUpPixels() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  void DrawPoint(float x, float y, float z = 0.0f) {
    glBegin(GL_POINTS);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(x, y, z);
    glEnd();
  }
  // The covered box (green pixels) and the number covered.
  struct Box {
    int x0 = 1 << 20, y0 = 1 << 20, x1 = -1, y1 = -1, count = 0;
  };
  Box Covered() {
    const unsigned char* p = pixels();
    Box b;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (p[(y * kWidth + x) * 4 + 1] != 0) {
          ++b.count;
          b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
          b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
        }
    return b;
  }
  void ExpectSquare(const Box& b, int x0, int y0, int width) {
    EXPECT_EQ(b.count, width * width);
    EXPECT_EQ(b.x0, x0);
    EXPECT_EQ(b.y0, y0);
    EXPECT_EQ(b.x1, x0 + width - 1);
    EXPECT_EQ(b.y1, y0 + width - 1);
  }
};

TEST_F(PointTest, InitialStateAndLimits) {
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 1.0f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MIN), 0.0f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MAX), 255.0f);  // Mesa: its largest size
  EXPECT_EQ(GetFloat(GL_POINT_FADE_THRESHOLD_SIZE), 1.0f);
  EXPECT_EQ((GetFloats<3>(GL_POINT_DISTANCE_ATTENUATION)), (std::array<GLfloat, 3>{1, 0, 0}));
  EXPECT_EQ(GetInt(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);
  EXPECT_EQ((GetFloats<2>(GL_POINT_SIZE_RANGE)), (std::array<GLfloat, 2>{1, 255}));
  EXPECT_EQ((GetFloats<2>(GL_SMOOTH_POINT_SIZE_RANGE)), (std::array<GLfloat, 2>{1, 255}));
  EXPECT_EQ((GetFloats<2>(GL_ALIASED_POINT_SIZE_RANGE)), (std::array<GLfloat, 2>{1, 255}));
  EXPECT_EQ((GetInts<2>(GL_ALIASED_POINT_SIZE_RANGE)), (std::array<GLint, 2>{1, 255}));
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_GRANULARITY), 0.1f);
  EXPECT_EQ(GetDouble(GL_SMOOTH_POINT_SIZE_GRANULARITY), double(0.1f));
  EXPECT_EQ(GetInt(GL_POINT_SIZE_GRANULARITY), 0);
  EXPECT_EQ(GetBool(GL_POINT_SMOOTH), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(PointTest, PointSizeValuesAndErrors) {
  glPointSize(2.5f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 2.5f);
  EXPECT_EQ(GetInt(GL_POINT_SIZE), 3);
  glPointSize(0.0f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPointSize(-1.0f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPointSize(-std::numeric_limits<float>::infinity());
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 2.5f);
  // NaN and huge sizes are stored (clamped when drawn).
  glPointSize(std::nanf(""));
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(std::isnan(GetFloat(GL_POINT_SIZE)));
  glPointSize(1e30f);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 1e30f);
  glPointSize(0.25f);  // below the minimum size: stored as given
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 0.25f);
  glBegin(GL_POINTS);
  glPointSize(3.0f);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 0.25f);
}

TEST_F(PointTest, PointParameterValuesAndErrors) {
  glPointParameterf(GL_POINT_SIZE_MIN, 2.0f);
  glPointParameteri(GL_POINT_SIZE_MAX, 40);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.5f);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MIN), 2.0f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MAX), 40.0f);
  EXPECT_EQ(GetFloat(GL_POINT_FADE_THRESHOLD_SIZE), 2.5f);
  EXPECT_EQ(GetInt(GL_POINT_FADE_THRESHOLD_SIZE), 3);
  // Negative sizes: GL_INVALID_VALUE, nothing changes.
  glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPointParameterf(GL_POINT_SIZE_MAX, -0.5f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, -2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MIN), 2.0f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MAX), 40.0f);
  // A minimum above the maximum is not an error.
  glPointParameterf(GL_POINT_SIZE_MIN, 50.0f);
  EXPECT_NO_GL_ERROR();
  // NaN and huge values are stored.
  glPointParameterf(GL_POINT_SIZE_MAX, std::nanf(""));
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(std::isnan(GetFloat(GL_POINT_SIZE_MAX)));
  glPointParameterf(GL_POINT_SIZE_MAX, 1e30f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MAX), 1e30f);

  // Attenuation: any values, negative and NaN included.
  const GLfloat att[3] = {-1.0f, 0.5f, 0.25f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ((GetFloats<3>(GL_POINT_DISTANCE_ATTENUATION)), (std::array<GLfloat, 3>{-1.0f, 0.5f, 0.25f}));
  const GLint iatt[3] = {2, 3, 4};
  glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, iatt);
  EXPECT_EQ((GetFloats<3>(GL_POINT_DISTANCE_ATTENUATION)), (std::array<GLfloat, 3>{2, 3, 4}));
  glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 5.0f);  // (5, 0, 0)
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ((GetFloats<3>(GL_POINT_DISTANCE_ATTENUATION)), (std::array<GLfloat, 3>{5, 0, 0}));

  // Sprite coordinate origin: two values, else GL_INVALID_VALUE.
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_FRONT);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, std::nanf(""));
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, static_cast<GLfloat>(GL_UPPER_LEFT));
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);

  // Other names: GL_INVALID_ENUM.
  glPointParameterf(GL_LINE_WIDTH, 1.0f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glPointParameteri(GL_POINT_SIZE, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);

  glBegin(GL_POINTS);
  glPointParameterf(GL_POINT_SIZE_MIN, 1.0f);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MIN), 50.0f);
}

TEST_F(PointTest, NullParameterPointerDoesNotCrash) {
  GLFX_SKIP_ON_MESA("glPointParameterfv(pname, NULL) dereferences the pointer and crashes");
  glPointParameterfv(GL_POINT_SIZE_MIN, nullptr);
  glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MIN), 0.0f);
}

TEST_F(PointTest, PushPopAttribAndLists) {
  glPushAttrib(GL_POINT_BIT);
  glPointSize(7.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 3.0f);
  glPopAttrib();
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 1.0f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MIN), 0.0f);

  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPointSize(5.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 9.0f);
  glEndList();
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 1.0f);  // compiled, not run
  glCallList(list);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 5.0f);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE_MAX), 9.0f);
  // An invalid size in a list is an error when the list runs.
  glNewList(list, GL_COMPILE);
  glPointSize(-2.0f);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(list);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetFloat(GL_POINT_SIZE), 5.0f);
  glDeleteLists(list, 1);
}

// Sizes round to whole pixels, .5 down; odd widths centre on the pixel that
// holds the vertex, even widths on the nearest pixel corner.
TEST_F(PointTest, AliasedSizesRoundHalfDown) {
  SetUpPixels();
  struct Case {
    float size, x, y;
    int x0, y0, width;
  } cases[] = {
      {1.0f, 10.5f, 20.5f, 10, 20, 1},   {1.0f, 10.9f, 20.1f, 10, 20, 1}, {0.25f, 10.5f, 20.5f, 10, 20, 1},
      {1.5f, 10.5f, 20.5f, 10, 20, 1},   {2.0f, 10.5f, 20.5f, 10, 20, 2}, {2.0f, 10.9f, 20.9f, 10, 20, 2},
      {2.5f, 10.5f, 20.5f, 10, 20, 2},   {2.51f, 10.5f, 20.5f, 9, 19, 3}, {3.0f, 10.2f, 20.7f, 9, 19, 3},
      {3.5f, 30.5f, 30.5f, 29, 29, 3},   {4.0f, 30.4f, 30.6f, 28, 29, 4}, {9.0f, 30.5f, 30.5f, 26, 26, 9},
      {16.0f, 32.0f, 32.0f, 24, 24, 16},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "size " << c.size << " at " << c.x << ", " << c.y);
    glClear(GL_COLOR_BUFFER_BIT);
    glPointSize(c.size);
    DrawPoint(c.x, c.y);
    ExpectSquare(Covered(), c.x0, c.y0, c.width);
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(PointTest, SizeClampsAndBadSizes) {
  SetUpPixels();
  // NaN: one pixel. 1e30: clamped to 255, the whole buffer.
  glPointSize(std::nanf(""));
  DrawPoint(30.5f, 30.5f);
  ExpectSquare(Covered(), 30, 30, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(1e30f);
  DrawPoint(30.5f, 30.5f);
  EXPECT_EQ(Covered().count, kWidth * kHeight);
  // GL_POINT_SIZE_MAX and _MIN clamp; the minimum wins over the maximum.
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(9.0f);
  glPointParameterf(GL_POINT_SIZE_MAX, 5.0f);
  DrawPoint(30.5f, 30.5f);
  ExpectSquare(Covered(), 28, 28, 5);
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(3.0f);
  glPointParameterf(GL_POINT_SIZE_MIN, 7.0f);
  DrawPoint(30.5f, 30.5f);
  ExpectSquare(Covered(), 27, 27, 7);
  // A NaN minimum wins too (Mesa's CLAMP): a size NaN point, one pixel.
  glClear(GL_COLOR_BUFFER_BIT);
  glPointParameterf(GL_POINT_SIZE_MIN, std::nanf(""));
  DrawPoint(30.5f, 30.5f);
  ExpectSquare(Covered(), 30, 30, 1);
  EXPECT_NO_GL_ERROR();
}

// A point whose centre is outside the view is dropped; one inside spills
// past the viewport's edge.
TEST_F(PointTest, ClippedByCentreOnly) {
  glViewport(16, 16, 32, 32);
  glMatrixMode(GL_PROJECTION);
  glOrtho(16, 48, 16, 48, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glPointSize(9.0f);
  DrawPoint(17.5f, 30.5f);
  ExpectSquare(Covered(), 13, 26, 9);
  glClear(GL_COLOR_BUFFER_BIT);
  DrawPoint(15.9f, 30.5f);
  EXPECT_EQ(Covered().count, 0);
  DrawPoint(30.5f, 30.5f, 1.5f);  // beyond the far plane
  DrawPoint(1e30f, 30.5f);
  DrawPoint(std::nanf(""), 30.5f);
  EXPECT_EQ(Covered().count, 0);
  EXPECT_NO_GL_ERROR();
}

// Distance attenuation: size / sqrt(a + b d + c d^2) with d = |z_eye|,
// clamped to [max(min, 1), min(max, 255)].
TEST_F(PointTest, DistanceAttenuation) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kWidth, 0, kHeight, 0, 100);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0, 0, 0, 0);
  const GLfloat att[3] = {0.0f, 0.0f, 1.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
  struct Case {
    float z;
    int width;
  } cases[] = {{-0.5f, 2}, {-1.0f, 1}, {-2.0f, 1}, {-0.25f, 4}, {-0.1f, 10}, {-0.2f, 5}, {-0.4f, 2}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "z " << c.z);
    glClear(GL_COLOR_BUFFER_BIT);
    DrawPoint(30.5f, 30.5f, c.z);
    EXPECT_EQ(Covered().count, c.width * c.width);
  }
  // A negative factor: RSQ takes its absolute value.
  const GLfloat negative[3] = {-1.0f, 0.0f, 0.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, negative);
  glPointSize(5.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  DrawPoint(30.5f, 30.5f, -1.0f);
  ExpectSquare(Covered(), 28, 28, 5);
  // NaN: the minimum size; zero: the maximum.
  const GLfloat nan[3] = {std::nanf(""), 0.0f, 0.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, nan);
  glClear(GL_COLOR_BUFFER_BIT);
  DrawPoint(30.5f, 30.5f, -1.0f);
  ExpectSquare(Covered(), 30, 30, 1);
  const GLfloat zero[3] = {0.0f, 0.0f, 0.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, zero);
  glClear(GL_COLOR_BUFFER_BIT);
  DrawPoint(30.5f, 30.5f, -1.0f);
  EXPECT_EQ(Covered().count, kWidth * kHeight);
  // (0.25, 0, 0) doubles the size; GL_POINT_SIZE_MAX clamps it.
  const GLfloat quarter[3] = {0.25f, 0.0f, 0.0f};
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quarter);
  glPointSize(2.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  DrawPoint(30.5f, 30.5f, -1.0f);
  ExpectSquare(Covered(), 29, 29, 4);
  glPointParameterf(GL_POINT_SIZE_MAX, 3.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  DrawPoint(30.5f, 30.5f, -1.0f);
  ExpectSquare(Covered(), 29, 29, 3);
  EXPECT_NO_GL_ERROR();
}

// The colour and depth of a point: the vertex's, flat or smooth; depth-tested.
TEST_F(PointTest, ColourAndDepth) {
  SetUpPixels();
  glEnable(GL_DEPTH_TEST);
  glPointSize(3.0f);
  glBegin(GL_POINTS);
  glColor3f(1.0f, 0.0f, 0.0f);
  glVertex3f(20.5f, 20.5f, -0.5f);  // window z 0.75
  glColor3f(0.0f, 0.0f, 1.0f);
  glVertex3f(21.5f, 20.5f, 0.5f);  // 0.25: in front of the red one
  glColor3f(0.0f, 1.0f, 0.0f);
  glVertex3f(22.5f, 20.5f, -0.9f);  // 0.95: behind the blue one
  glEnd();
  const unsigned char* p = pixels();
  auto at = [&](int x, int y) { return p + (y * kWidth + x) * 4; };
  EXPECT_EQ(at(19, 20)[0], 255);  // red, left of the blue square
  EXPECT_EQ(at(21, 20)[2], 255);  // blue
  EXPECT_EQ(at(22, 20)[2], 255);
  EXPECT_EQ(at(22, 20)[1], 0);
  EXPECT_EQ(at(23, 20)[1], 255);  // green, right of it
  EXPECT_EQ(at(23, 20)[3], 255);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
