// glLineWidth, glLineStipple, GL_LINE_SMOOTH/GL_LINE_STIPPLE and the line
// queries (GL 2.1 §3.5, tables 6.15 and 6.31), as Mesa 22.3 answers them;
// and bad input that must not crash. Built against Mesa too.
#include <cmath>
#include <limits>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using LineTest = GLTest;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// One unit = one pixel, GL window coordinates.
void OrthoPixels() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kWidth, 0, kHeight, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

// The pixels of row y (GL window coordinates) whose red channel is set.
std::vector<int> RedPixelsOfRow(const unsigned char* p, int y) {
  std::vector<int> xs;
  for (int x = 0; x < kWidth; ++x)
    if (p[4 * (y * kWidth + x)] != 0) xs.push_back(x);
  return xs;
}

int CountLit(const unsigned char* p) {
  int n = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) n += p[4 * i] != 0 || p[4 * i + 1] != 0 || p[4 * i + 2] != 0;
  return n;
}

void ClearBlack() {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
}

TEST_F(LineTest, InitialState) {
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 1.0f);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_PATTERN), 0xffff);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_LINE_STIPPLE), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

// llvmpipe's limits: 1 to 255 for aliased and smooth lines, granularity 0.1.
TEST_F(LineTest, WidthRangesAsMesaReportsThem) {
  const auto range = GetFloats<2>(GL_LINE_WIDTH_RANGE);
  EXPECT_EQ(range[0], 1.0f);
  EXPECT_EQ(range[1], 255.0f);
  const auto smooth = GetFloats<2>(GL_SMOOTH_LINE_WIDTH_RANGE);
  EXPECT_EQ(smooth[0], 1.0f);
  EXPECT_EQ(smooth[1], 255.0f);
  const auto aliased = GetFloats<2>(GL_ALIASED_LINE_WIDTH_RANGE);
  EXPECT_EQ(aliased[0], 1.0f);
  EXPECT_EQ(aliased[1], 255.0f);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH_GRANULARITY), 0.1f);
  EXPECT_EQ(GetFloat(GL_SMOOTH_LINE_WIDTH_GRANULARITY), 0.1f);
  EXPECT_EQ(GetInt(GL_ALIASED_LINE_WIDTH_RANGE), 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(LineTest, WidthIsStoredAsGivenAndReadBackUnclamped) {
  glLineWidth(2.5f);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 2.5f);
  EXPECT_EQ(GetInt(GL_LINE_WIDTH), 3);  // rounded (§6.1.2)
  glLineWidth(1000.0f);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 1000.0f);
  glLineWidth(0.25f);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 0.25f);
  glLineWidth(kInf);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), kInf);
  glLineWidth(kNaN);
  EXPECT_TRUE(std::isnan(GetFloat(GL_LINE_WIDTH)));
  EXPECT_NO_GL_ERROR();
}

TEST_F(LineTest, NonPositiveWidthIsInvalidValueAndChangesNothing) {
  glLineWidth(3.0f);
  glLineWidth(0.0f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glLineWidth(-1.0f);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glLineWidth(-kInf);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 3.0f);
}

TEST_F(LineTest, StippleFactorIsClampedNotAnError) {
  glLineStipple(3, 0x1234);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 3);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_PATTERN), 0x1234);
  glLineStipple(0, 0x00ff);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_PATTERN), 0x00ff);
  glLineStipple(1000, 0x0f0f);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 256);
  glLineStipple(-7, 0xffff);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(LineTest, EnablesAreSettable) {
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_LINE_STIPPLE);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_TRUE);
  EXPECT_EQ(GetBool(GL_LINE_STIPPLE), GL_TRUE);
  glDisable(GL_LINE_SMOOTH);
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(LineTest, LineStateIsPushedAndPopped) {
  glPushAttrib(GL_LINE_BIT);
  glLineWidth(4.0f);
  glLineStipple(9, 0x0101);
  glEnable(GL_LINE_STIPPLE);
  glEnable(GL_LINE_SMOOTH);
  glPopAttrib();
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 1.0f);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 1);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_PATTERN), 0xffff);
  EXPECT_EQ(glIsEnabled(GL_LINE_STIPPLE), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(LineTest, InsideBeginEndIsInvalidOperation) {
  glBegin(GL_LINES);
  glLineWidth(2.0f);
  glLineStipple(2, 0x0f0f);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 1.0f);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 1);
}

TEST_F(LineTest, CompiledIntoDisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glLineWidth(5.0f);
  glLineStipple(4, 0x3333);
  glEndList();
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 1.0f);
  glCallList(list);
  EXPECT_EQ(GetFloat(GL_LINE_WIDTH), 5.0f);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_REPEAT), 4);
  EXPECT_EQ(GetInt(GL_LINE_STIPPLE_PATTERN), 0x3333);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

// A 1-wide line draws its first endpoint's pixel and not its last.
TEST_F(LineTest, FirstEndpointDrawnLastNot) {
  OrthoPixels();
  ClearBlack();
  glColor3f(1, 0, 0);
  glBegin(GL_LINES);
  glVertex2f(2.5f, 10.5f);
  glVertex2f(10.5f, 10.5f);
  glVertex2f(10.5f, 20.5f);
  glVertex2f(2.5f, 20.5f);
  glEnd();
  const unsigned char* p = pixels();
  EXPECT_EQ(RedPixelsOfRow(p, 10), (std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(RedPixelsOfRow(p, 20), (std::vector<int>{3, 4, 5, 6, 7, 8, 9, 10}));
}

// Widths round to an integer, .5 up; an x-major line widens vertically.
TEST_F(LineTest, WideLinesRoundTheirWidth) {
  OrthoPixels();
  const float widths[] = {1.5f, 2.5f, 3.0f};
  const int rows[] = {2, 3, 3};
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(widths[k]);
    ClearBlack();
    glLineWidth(widths[k]);
    glColor3f(1, 0, 0);
    glBegin(GL_LINES);
    glVertex2f(4.5f, 30.5f);
    glVertex2f(40.5f, 30.5f);
    glEnd();
    EXPECT_EQ(CountLit(pixels()), 36 * rows[k]);
  }
}

TEST_F(LineTest, ZeroLengthLineDrawsNothing) {
  OrthoPixels();
  ClearBlack();
  glColor3f(1, 0, 0);
  glBegin(GL_LINES);
  glVertex2f(20.5f, 20.5f);
  glVertex2f(20.5f, 20.5f);
  glEnd();
  EXPECT_EQ(CountLit(pixels()), 0);
}

// Stipple 0x00ff, factor 1: 8 pixels on, 8 off; it restarts at each GL_LINES
// line and carries on along a strip.
TEST_F(LineTest, StippleKeepsThePatternsPixels) {
  OrthoPixels();
  ClearBlack();
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x00ff);
  glColor3f(1, 0, 0);
  glBegin(GL_LINE_STRIP);
  glVertex2f(0.5f, 5.5f);
  glVertex2f(12.5f, 5.5f);
  glVertex2f(40.5f, 5.5f);
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(0.5f, 9.5f);
  glVertex2f(12.5f, 9.5f);
  glVertex2f(12.5f, 9.5f);
  glVertex2f(40.5f, 9.5f);
  glEnd();
  const unsigned char* p = pixels();
  std::vector<int> strip, lines;
  for (int x = 0; x < 40; ++x) {
    if ((x / 8) % 2 == 0) strip.push_back(x);
    if (x < 12 ? x < 8 : (x - 12) % 16 < 8) lines.push_back(x);
  }
  EXPECT_EQ(RedPixelsOfRow(p, 5), strip);
  EXPECT_EQ(RedPixelsOfRow(p, 9), lines);
}

// Bad input never crashes: NaN and huge widths, endpoints at 1e30 or NaN,
// stipple factors out of range.
TEST_F(LineTest, BadInputDrawsWithoutCrashing) {
  OrthoPixels();
  const float widths[] = {kNaN, kInf, 1e30f, 255.0f, 0.001f, 1.0f};
  for (float w : widths) {
    glLineWidth(w);
    for (int smooth = 0; smooth < 2; ++smooth) {
      if (smooth)
        glEnable(GL_LINE_SMOOTH);
      else
        glDisable(GL_LINE_SMOOTH);
      for (int stipple = 0; stipple < 3; ++stipple) {
        if (stipple)
          glEnable(GL_LINE_STIPPLE);
        else
          glDisable(GL_LINE_STIPPLE);
        glLineStipple(stipple == 1 ? 0 : 1000, 0x0f0f);
        glBegin(GL_LINE_STRIP);
        glVertex2f(1e30f, 10.0f);
        glVertex2f(5.0f, 5.0f);
        glVertex2f(kNaN, 3.0f);
        glVertex2f(30.0f, kNaN);
        glVertex2f(-1e30f, -1e30f);
        glVertex2f(60.0f, 60.0f);
        glVertex2f(kInf, -kInf);
        glVertex4f(1.0f, 2.0f, 0.0f, 0.0f);
        glVertex2f(32.0f, 32.0f);
        glEnd();
      }
    }
  }
  glFinish();
  EXPECT_NO_GL_ERROR();
}

// A NaN width draws as width 1 (Mesa's CLAMP turns NaN into the minimum).
TEST_F(LineTest, NaNWidthDrawsOneWide) {
  OrthoPixels();
  ClearBlack();
  glLineWidth(kNaN);
  glColor3f(1, 0, 0);
  glBegin(GL_LINES);
  glVertex2f(4.5f, 30.5f);
  glVertex2f(40.5f, 30.5f);
  glEnd();
  EXPECT_EQ(CountLit(pixels()), 36);
}

}  // namespace
}  // namespace glfx_test
