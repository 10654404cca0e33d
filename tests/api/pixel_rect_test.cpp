// Pixel rectangles (GL 2.1 §3.6.4, §3.7, §4.3.3) and glWindowPos (GL 1.4):
// what glBitmap, glDrawPixels and glCopyPixels draw, read back with
// glReadPixels, their errors and bad input. Run on libglfixed and on Mesa.
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "gl_test_fixture.h"
#include "pixel_readback.h"

namespace glfx_test {
namespace {

using PixelRectTest = GLTest;

// A 16 x 4 bitmap: row j has bits set at the columns of the pattern.
const GLubyte kBits[4][2] = {{0xff, 0x00}, {0x81, 0x81}, {0xaa, 0x55}, {0x00, 0x01}};

TEST_F(PixelRectTest, BitmapDrawsTheRasterColourAtTheFlooredPosition) {
  PixelProjection();
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor4f(1, 0.5f, 0.25f, 0.75f);
  glRasterPos2f(10.6f, 20.2f);  // window (10.6, 20.2), origin (0.5, 0.1): (10, 20)
  glBitmap(16, 4, 0.5f, 0.1f, 3, 4, &kBits[0][0]);
  const std::vector<unsigned char> p = ReadAll();
  const std::array<int, 4> c = {255, 128, 64, 191}, black = {0, 0, 0, 0};
  EXPECT_EQ(CountColored(p, c), 8 + 4 + 8 + 1);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(At(p, 10 + i, 20), c) << i;  // row 0: 0xff 0x00
  EXPECT_EQ(At(p, 18, 20), black);
  EXPECT_EQ(At(p, 10, 21), c);  // row 1: 0x81 0x81
  EXPECT_EQ(At(p, 17, 21), c);
  EXPECT_EQ(At(p, 25, 21), c);
  EXPECT_EQ(At(p, 11, 22), black);  // row 2: 0xaa 0x55
  EXPECT_EQ(At(p, 10, 22), c);
  EXPECT_EQ(At(p, 25, 23), c);  // row 3: 0x00 0x01
  // The raster position moved by (3, 4).
  GLfloat pos[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_FLOAT_EQ(pos[0], 13.6f);
  EXPECT_FLOAT_EQ(pos[1], 24.2f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(PixelRectTest, BitmapGoesThroughTheDepthTestWithTheRasterDepth) {
  PixelProjection();
  ClearBlack();
  // A quad at depth 0.5 (z = 0 in this ortho) over the left half.
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 0, 1);
  glRectf(0, 0, 32, 64);
  static GLubyte ones[8 * 8];
  for (GLubyte& b : ones) b = 0xff;
  glColor3f(0, 1, 0);
  glRasterPos3f(24, 8, 0.5f);  // depth 0.25: in front
  glBitmap(16, 8, 0, 0, 0, 0, ones);
  glColor3f(1, 0, 0);
  glRasterPos3f(24, 24, -0.5f);  // depth 0.75: behind the quad
  glBitmap(16, 8, 0, 0, 0, 0, ones);
  const std::vector<unsigned char> p = ReadAll();
  const std::array<int, 4> green = {0, 255, 0, 255}, red = {255, 0, 0, 255}, blue = {0, 0, 255, 255};
  EXPECT_EQ(At(p, 24, 8), green);
  EXPECT_EQ(At(p, 39, 15), green);
  EXPECT_EQ(At(p, 24, 24), blue);  // hidden
  EXPECT_EQ(At(p, 32, 24), red);   // right of the quad
  EXPECT_EQ(CountColored(p, red), 8 * 8);
  // The bitmap wrote its depth: a quad at depth 0.3 hides only where it is not.
  GLfloat z = 0;
  glReadPixels(30, 10, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  EXPECT_NEAR(z, 0.25f, 1e-6f);
  glDisable(GL_DEPTH_TEST);
}

// Mesa gathers bitmaps in its bitmap cache and draws them later with the
// state it validated last: that of the last glBitmap call (a Mesa departure
// the library matches). A depth test enabled after a glBitmap does not apply
// to it, even at the next draw; one disabled before the next glBitmap does.
TEST_F(PixelRectTest, CachedBitmapsTakeTheStateOfTheLastBitmap) {
  PixelProjection();
  ClearBlack();
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 0, 1);
  glRectf(0, 0, 64, 64);  // depth 0.5 everywhere
  glDisable(GL_DEPTH_TEST);
  static GLubyte ones[8 * 8];
  for (GLubyte& b : ones) b = 0xff;
  glColor3f(1, 1, 0);
  glRasterPos3f(8, 8, -0.5f);  // depth 0.75: behind
  glBitmap(8, 8, 0, 0, 0, 0, ones);
  glEnable(GL_DEPTH_TEST);
  glRectf(60, 60, 61, 61);  // the cache is drawn first, depth test off
  // Cached with the depth test on, then a glBitmap with it off: drawn off.
  glRasterPos3f(20, 8, -0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, ones);
  glColor3f(1, 1, 1);
  glRasterPos3f(40, 8, -0.5f);
  glDisable(GL_DEPTH_TEST);
  glBitmap(8, 8, 0, 0, 0, 0, ones);
  glEnable(GL_DEPTH_TEST);
  // Cached with it off (white), then a glBitmap with it on: drawn on (hidden).
  glColor3f(0, 1, 1);
  glRasterPos3f(8, 40, -0.5f);
  glBitmap(8, 8, 0, 0, 0, 0, ones);
  glFinish();
  glDisable(GL_DEPTH_TEST);
  const std::vector<unsigned char> p = ReadAll();
  const std::array<int, 4> yellow = {255, 255, 0, 255}, white = {255, 255, 255, 255}, blue = {0, 0, 255, 255};
  EXPECT_EQ(At(p, 10, 10), yellow);
  EXPECT_EQ(At(p, 22, 10), yellow);
  EXPECT_EQ(At(p, 42, 10), blue);  // flushed by the cyan glBitmap, depth test on
  EXPECT_EQ(CountColored(p, white), 0);
  EXPECT_EQ(At(p, 10, 42), blue);
}

TEST_F(PixelRectTest, BitmapUnpackSettingsAndScissor) {
  PixelProjection();
  ClearBlack();
  // A 3 x 2 bitmap read from a 20-pixel-wide image, skipping 9 pixels and
  // one row, rows padded to 2 bytes... with alignment 4: 4 bytes a row.
  const GLubyte image[3][4] = {{0, 0, 0, 0}, {0x00, 0x60, 0, 0}, {0x00, 0x20, 0, 0}};
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 20);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 9);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glColor3f(1, 1, 1);
  glRasterPos2i(5, 5);
  glBitmap(3, 2, 0, 0, 0, 0, &image[0][0]);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  std::vector<unsigned char> p = ReadAll();
  const std::array<int, 4> white = {255, 255, 255, 255};
  // Bits 9, 10 of row 1 (0x60 in byte 1: bits 1, 2) and bit 10 of row 2.
  EXPECT_EQ(CountColored(p, white), 3);
  EXPECT_EQ(At(p, 5, 5), white);
  EXPECT_EQ(At(p, 6, 5), white);
  EXPECT_EQ(At(p, 6, 6), white);
  // The scissor cuts a bitmap.
  ClearBlack();
  static GLubyte ones[4 * 16];
  for (GLubyte& b : ones) b = 0xff;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_SCISSOR_TEST);
  glScissor(10, 10, 5, 3);
  glRasterPos2i(0, 0);
  glBitmap(32, 16, 0, 0, 0, 0, ones);
  glDisable(GL_SCISSOR_TEST);
  p = ReadAll();
  EXPECT_EQ(CountColored(p, white), 15);
  EXPECT_EQ(At(p, 10, 10), white);
  EXPECT_EQ(At(p, 14, 12), white);
}

TEST_F(PixelRectTest, BitmapInADisplayListKeepsItsBits) {
  PixelProjection();
  ClearBlack();
  GLubyte bits[2] = {0xf0, 0x00};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBitmap(8, 1, 0, 0, 10, 0, bits);
  glEndList();
  bits[0] = 0;
  glColor3f(1, 0, 0);
  glRasterPos2i(4, 4);
  glCallList(list);
  glCallList(list);
  const std::vector<unsigned char> p = ReadAll();
  const std::array<int, 4> red = {255, 0, 0, 255};
  EXPECT_EQ(CountColored(p, red), 8);
  EXPECT_EQ(At(p, 4, 4), red);
  EXPECT_EQ(At(p, 17, 4), red);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(PixelRectTest, BitmapBadInputNeverCrashes) {
  PixelProjection();
  ClearBlack();
  static GLubyte ones[64 * 64 / 8];
  for (GLubyte& b : ones) b = 0xff;
  glBitmap(-1, 4, 0, 0, 0, 0, ones);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glRasterPos2i(4, 4);
  glBitmap(8, 8, 0, 0, 0, 0, nullptr);  // no data: nothing drawn, the position moves
  glBitmap(8, 8, 1e30f, -1e30f, 0, 0, ones);
  glBitmap(8, 8, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, ones);
  glBitmap(64, 64, 0, 0, 1e9f, 1e9f, ones);
  glBitmap(64, 64, 0, 0, -3e9f, -3e9f, ones);
  glBitmap(64, 64, 0, 0, 0, 0, ones);
  glFinish();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // An invalid raster position: nothing drawn, no move.
  ClearBlack();
  glRasterPos2i(-10, 4);
  glBitmap(8, 8, 0, 0, 20, 0, ones);
  glFinish();
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(CountColored(p, {0, 0, 0, 0}), kWidth * kHeight);
  GLint valid = 1;
  glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 0);
}

}  // namespace
}  // namespace glfx_test

namespace glfx_test {
namespace {

TEST_F(PixelRectTest, WindowPosSetsAValidPositionInWindowCoordinates) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 1, 0, 1, -1, 1);  // glWindowPos ignores every matrix
  glRasterPos2f(-5, -5);
  GLint valid = 1;
  glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 0);
  glDepthRange(0.25, 0.75);
  glColor4f(2, 0.5f, -1, 1);
  glWindowPos3f(10.5f, -3.25f, 0.5f);
  GLfloat pos[4], color[4];
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  glGetFloatv(GL_CURRENT_RASTER_COLOR, color);
  glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, 1);
  EXPECT_FLOAT_EQ(pos[0], 10.5f);
  EXPECT_FLOAT_EQ(pos[1], -3.25f);
  EXPECT_FLOAT_EQ(pos[2], 0.5f);
  EXPECT_FLOAT_EQ(pos[3], 1.0f);
  EXPECT_FLOAT_EQ(color[0], 1.0f);
  EXPECT_FLOAT_EQ(color[1], 0.5f);
  EXPECT_FLOAT_EQ(color[2], 0.0f);
  glWindowPos2i(3, 4);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_FLOAT_EQ(pos[2], 0.25f);  // z 0 through the depth range
  const GLdouble d[3] = {7, 8, 2};
  glWindowPos3dv(d);
  glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
  EXPECT_FLOAT_EQ(pos[0], 7.0f);
  EXPECT_FLOAT_EQ(pos[2], 0.75f);  // z clamped to 1 first
  glDepthRange(0, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(PixelRectTest, WindowPosPlacesABitmap) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLubyte bits[1] = {0x80};
  glColor3f(0, 1, 0);
  glWindowPos2i(30, 31);
  glBitmap(1, 1, 0, 0, 0, 0, bits);
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 30, 31), (std::array<int, 4>{0, 255, 0, 255}));
  EXPECT_EQ(CountColored(p, {0, 255, 0, 255}), 1);
}

}  // namespace
}  // namespace glfx_test

namespace glfx_test {
namespace {

TEST_F(PixelRectTest, PixelZoomIsStoredPushedAndListed) {
  glPixelZoom(-2.5f, 0.0f);
  GLfloat z[2];
  glGetFloatv(GL_ZOOM_X, &z[0]);
  glGetFloatv(GL_ZOOM_Y, &z[1]);
  EXPECT_FLOAT_EQ(z[0], -2.5f);
  EXPECT_FLOAT_EQ(z[1], 0.0f);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelZoom(3, 4);
  glPopAttrib();
  glGetFloatv(GL_ZOOM_X, &z[0]);
  EXPECT_FLOAT_EQ(z[0], -2.5f);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPixelZoom(5, 6);
  glEndList();
  glGetFloatv(GL_ZOOM_X, &z[0]);
  EXPECT_FLOAT_EQ(z[0], -2.5f);
  glCallList(list);
  glGetFloatv(GL_ZOOM_Y, &z[1]);
  EXPECT_FLOAT_EQ(z[1], 6.0f);
  glDeleteLists(list, 1);
  glPixelZoom(1, 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace glfx_test
