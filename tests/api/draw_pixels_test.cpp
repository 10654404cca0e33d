// glDrawPixels and glCopyPixels of colour (GL 2.1 §3.6.4, §4.3.3): where the
// pixels land (the rounded raster position, the pixel zoom), what they hold
// after glReadPixels, their errors and bad input. Run on libglfixed and on Mesa.
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "gl_test_fixture.h"
#include "pixel_readback.h"

namespace glfx_test {
namespace {

using DrawPixelsTest = GLTest;

int CountNonBlack(const std::vector<unsigned char>& p) {
  return kWidth * kHeight - CountColored(p, {0, 0, 0, 0});
}

// A 2 x 2 image: bottom row red, green; top row blue, white-ish.
const GLubyte kImage[2][2][4] = {{{255, 0, 0, 255}, {0, 255, 0, 128}},
                                 {{0, 0, 255, 64}, {200, 100, 50, 255}}};

TEST_F(DrawPixelsTest, ImageLandsAtTheRoundedRasterPosition) {
  PixelProjection();
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2f(10.5f, 20.4f);  // lroundf: (11, 20)
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kImage);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 11, 20), (std::array<int, 4>{255, 0, 0, 255}));
  EXPECT_EQ(At(p, 12, 20), (std::array<int, 4>{0, 255, 0, 128}));
  EXPECT_EQ(At(p, 11, 21), (std::array<int, 4>{0, 0, 255, 64}));
  EXPECT_EQ(At(p, 12, 21), (std::array<int, 4>{200, 100, 50, 255}));
  EXPECT_EQ(CountNonBlack(p), 4);
}

TEST_F(DrawPixelsTest, NegativeZoomMirrorsFromTheRasterPosition) {
  PixelProjection();
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(10, 10);
  glPixelZoom(-2, -1);  // covers x 6..9, y 8..9
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kImage);
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(CountNonBlack(p), 8);
  EXPECT_EQ(At(p, 9, 9), (std::array<int, 4>{255, 0, 0, 255}));
  EXPECT_EQ(At(p, 8, 9), (std::array<int, 4>{255, 0, 0, 255}));
  EXPECT_EQ(At(p, 7, 9), (std::array<int, 4>{0, 255, 0, 128}));
  EXPECT_EQ(At(p, 6, 8), (std::array<int, 4>{200, 100, 50, 255}));
}

TEST_F(DrawPixelsTest, FractionalZoomCoversThePixelCentresInside) {
  PixelProjection();
  ClearBlack();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glRasterPos2i(4, 4);
  glPixelZoom(1.5f, 0.5f);  // x [4, 7): 3 columns; y [4, 5): 1 row
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, kImage);
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(CountNonBlack(p), 3);
  EXPECT_EQ(At(p, 4, 4), (std::array<int, 4>{0, 0, 255, 64}));  // t = 0.5: the top row
}

TEST_F(DrawPixelsTest, FragmentsTakeTheRasterDepthThroughTheDepthTest) {
  PixelProjection();
  ClearBlack();
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 1, 1);
  glRectf(0, 0, 8, 8);  // depth 0.5
  const GLubyte px[4] = {10, 20, 30, 40};
  glRasterPos3f(2, 2, 0.5f);  // window z 0.25: in front
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glRasterPos3f(4, 4, -0.5f);  // window z 0.75: behind
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 2, 2), (std::array<int, 4>{10, 20, 30, 40}));
  EXPECT_EQ(At(p, 4, 4), (std::array<int, 4>{255, 255, 255, 255}));
}

TEST_F(DrawPixelsTest, InvalidRasterPositionDrawsNothing) {
  PixelProjection();
  ClearBlack();
  glRasterPos3f(5, 5, 3);  // outside the near/far planes
  const GLubyte px[4] = {10, 20, 30, 40};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(CountNonBlack(ReadAll()), 0);
}

TEST_F(DrawPixelsTest, ErrorsChangeNothing) {
  PixelProjection();
  ClearBlack();
  const GLubyte px[16] = {255, 255, 255, 255};
  glRasterPos2i(1, 1);
  glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glDrawPixels(1, 1, GL_RGBA8, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glDrawPixels(1, 1, GL_RGBA, GL_RGBA, px);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, px);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glCopyPixels(0, 0, 1, -1, GL_COLOR);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  glCopyPixels(0, 0, 1, 1, GL_RGBA);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(CountNonBlack(ReadAll()), 0);
}

TEST_F(DrawPixelsTest, NullPixelsAreOutOfMemoryAndDrawNothing) {
  PixelProjection();
  ClearBlack();
  glRasterPos2i(1, 1);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  EXPECT_EQ(CountNonBlack(ReadAll()), 0);
  // Wholly outside the window without zoom: cut away before the image is read.
  glRasterPos2i(0, 0);
  glBitmap(0, 0, 0, 0, -100000, 0, nullptr);
  glDrawPixels(1000, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(DrawPixelsTest, BadZoomsAndFarPositionsDoNotCrash) {
  PixelProjection();
  ClearBlack();
  const GLubyte px[4] = {10, 20, 30, 40};
  glRasterPos2i(5, 5);
  const float zooms[] = {0.0f,   std::numeric_limits<float>::quiet_NaN(), 1e30f,
                         -1e30f, std::numeric_limits<float>::infinity(),  1e-30f};
  for (float z : zooms) {
    glPixelZoom(z, 1);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glPixelZoom(1, z);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glCopyPixels(0, 0, 4, 4, GL_COLOR);
  }
  glPixelZoom(1, 1);
  glBitmap(0, 0, 0, 0, 1e9f, -1e9f, nullptr);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  glCopyPixels(std::numeric_limits<int>::max() - 2, 0, 100, 100, GL_COLOR);
  glCopyPixels(-1000000, -1000000, 10, 10, GL_COLOR);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(DrawPixelsTest, UnpackBufferOverrunIsInvalidOperation) {
  PixelProjection();
  ClearBlack();
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b);
  const GLubyte px[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof(px), px, GL_STATIC_DRAW);
  glRasterPos2i(2, 2);
  glDrawPixels(3, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glDrawPixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glDeleteBuffers(1, &b);
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 2, 2), (std::array<int, 4>{1, 2, 3, 4}));
  EXPECT_EQ(At(p, 3, 2), (std::array<int, 4>{5, 6, 7, 8}));
  EXPECT_EQ(CountNonBlack(p), 2);
}

TEST_F(DrawPixelsTest, DisplayListKeepsTheImageOfCompileTime) {
  PixelProjection();
  ClearBlack();
  GLubyte px[4] = {10, 20, 30, 40};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glEndList();
  px[0] = 99;
  glRasterPos2i(7, 7);
  glCallList(list);
  EXPECT_EQ(At(ReadAll(), 7, 7), (std::array<int, 4>{10, 20, 30, 40}));
  glDeleteLists(list, 1);
}

TEST_F(DrawPixelsTest, OverlappingCopyReadsTheSourceFirst) {
  PixelProjection();
  ClearBlack();
  const GLubyte row[4][4] = {{10, 0, 0, 255}, {20, 0, 0, 255}, {30, 0, 0, 255}, {40, 0, 0, 255}};
  glRasterPos2i(0, 0);
  glDrawPixels(4, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
  glRasterPos2i(1, 0);
  glCopyPixels(0, 0, 4, 1, GL_COLOR);
  const std::vector<unsigned char> p = ReadAll();
  for (int i = 0; i < 4; ++i) EXPECT_EQ(At(p, i + 1, 0)[0], 10 * (i + 1)) << i;
  EXPECT_EQ(At(p, 0, 0)[0], 10);
}

TEST_F(DrawPixelsTest, CopyWithoutFragmentOperationsIgnoresTheColourMask) {
  PixelProjection();
  ClearBlack();
  const GLubyte px[4] = {10, 20, 30, 40};
  glRasterPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
  glRasterPos2i(5, 5);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);  // Mesa's blit: every channel
  glPixelZoom(1, 2);
  glRasterPos2i(8, 8);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);  // zoomed: the quad, the mask applies
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const std::vector<unsigned char> p = ReadAll();
  EXPECT_EQ(At(p, 5, 5), (std::array<int, 4>{10, 20, 30, 40}));
  EXPECT_EQ(At(p, 8, 8), (std::array<int, 4>{0, 20, 30, 40}));
  EXPECT_EQ(At(p, 8, 9), (std::array<int, 4>{0, 20, 30, 40}));
}

TEST_F(DrawPixelsTest, CopyWithoutAReadBufferIsInvalidOperation) {
  PixelProjection();
  ClearBlack();
  glReadBuffer(GL_NONE);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glRasterPos2i(5, 5);
  glCopyPixels(0, 0, 2, 2, GL_COLOR);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glReadBuffer(GL_FRONT);
}

}  // namespace
}  // namespace glfx_test
