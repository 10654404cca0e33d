// glRect in all its forms (GL 2.1 §2.10): the rectangle it draws, its errors,
// and its place in display lists. Run on libglfixed and on Mesa.
#include <array>
#include <limits>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using RectTest = GLTest;

// One pixel of the client buffer (row 0 at the bottom), as RGBA bytes.
std::array<int, 4> At(const unsigned char* p, int x, int y) {
  const unsigned char* q = p + (static_cast<size_t>(y) * kWidth + x) * 4;
  return {q[0], q[1], q[2], q[3]};
}

// Pixel-aligned projection: object (x, y) is window (x, y).
void PixelProjection() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kWidth, 0, kHeight, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int CountColored(const unsigned char* p, std::array<int, 4> c) {
  int n = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) n += At(p, x, y) == c;
  return n;
}

TEST_F(RectTest, EveryFormFillsItsRectangle) {
  PixelProjection();
  const std::array<int, 4> red = {255, 0, 0, 255};
  auto check = [&](auto draw, const char* form) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 0, 0, 1);
    draw();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << form;
    const unsigned char* p = pixels();
    // [4, 20) x [8, 40): 16 x 32 pixels, corners included, nothing outside.
    EXPECT_EQ(CountColored(p, red), 16 * 32) << form;
    EXPECT_EQ(At(p, 4, 8), red) << form;
    EXPECT_EQ(At(p, 19, 39), red) << form;
    EXPECT_NE(At(p, 20, 39), red) << form;
    EXPECT_NE(At(p, 19, 40), red) << form;
  };
  const GLdouble d1[2] = {4, 8}, d2[2] = {20, 40};
  const GLfloat f1[2] = {4, 8}, f2[2] = {20, 40};
  const GLint i1[2] = {4, 8}, i2[2] = {20, 40};
  const GLshort s1[2] = {4, 8}, s2[2] = {20, 40};
  check([] { glRectd(4, 8, 20, 40); }, "glRectd");
  check([] { glRectf(4, 8, 20, 40); }, "glRectf");
  check([] { glRecti(4, 8, 20, 40); }, "glRecti");
  check([] { glRects(4, 8, 20, 40); }, "glRects");
  check([&] { glRectdv(d1, d2); }, "glRectdv");
  check([&] { glRectfv(f1, f2); }, "glRectfv");
  check([&] { glRectiv(i1, i2); }, "glRectiv");
  check([&] { glRectsv(s1, s2); }, "glRectsv");
  // Corners given the other way round: the same pixels (a clockwise quad,
  // not culled).
  check([] { glRectf(20, 40, 4, 8); }, "glRectf reversed");
}

TEST_F(RectTest, IsBackFacingWhenItsCornersAreReversed) {
  PixelProjection();
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor4f(0, 1, 0, 1);
  glRectf(20, 40, 4, 8);  // (x2 < x1, y2 < y1): counter-clockwise again
  glRectf(30, 8, 40, 40);
  glRectf(50, 8, 44, 40);  // only x reversed: clockwise, culled
  const unsigned char* p = pixels();
  const std::array<int, 4> green = {0, 255, 0, 255};
  EXPECT_EQ(At(p, 10, 20), green);
  EXPECT_EQ(At(p, 35, 20), green);
  EXPECT_NE(At(p, 47, 20), green);
}

TEST_F(RectTest, InsideBeginEndIsAnInvalidOperation) {
  PixelProjection();
  glBegin(GL_TRIANGLES);
  glRectf(0, 0, 10, 10);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(RectTest, IsCompiledIntoDisplayLists) {
  PixelProjection();
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glColor4f(0, 0, 1, 1);
  glRecti(10, 10, 30, 20);
  glEndList();
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(CountColored(pixels(), {0, 0, 255, 255}), 0) << "GL_COMPILE drew";
  glCallList(list);
  EXPECT_EQ(CountColored(pixels(), {0, 0, 255, 255}), 20 * 10);
  // Inside the list's glBegin/glEnd it is a compiled GL_INVALID_OPERATION.
  glNewList(list, GL_COMPILE);
  glBegin(GL_QUADS);
  glRectf(0, 0, 1, 1);
  glEnd();
  glEndList();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glCallList(list);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glDeleteLists(list, 1);
}

TEST_F(RectTest, HugeAndNanCornersDoNotCrash) {
  PixelProjection();
  glRectf(-1e30f, -1e30f, 1e30f, 1e30f);
  glRectd(1e300, 0, -1e300, 10);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  glRectf(nan, 0, 10, nan);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

#ifndef TESTING_AGAINST_MESA
TEST_F(RectTest, NullVectorsDrawNothing) {
  PixelProjection();
  glClear(GL_COLOR_BUFFER_BIT);
  const GLfloat v[2] = {0, 0};
  glRectfv(nullptr, v);
  glRectiv(nullptr, nullptr);
  EXPECT_EQ(CountColored(pixels(), {0, 0, 0, 0}), kWidth * kHeight);
}
#endif

}  // namespace
}  // namespace glfx_test
