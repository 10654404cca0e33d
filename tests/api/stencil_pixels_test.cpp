// Pixel rectangles of stencil and depth (GL 2.1 §3.6.4, §4.3.2, §4.3.3;
// EXT_packed_depth_stencil): glDrawPixels(GL_STENCIL_INDEX) of every index
// type and glDrawPixels(GL_DEPTH_STENCIL); glCopyPixels(GL_STENCIL),
// (GL_DEPTH) and (GL_DEPTH_STENCIL); glReadPixels(GL_STENCIL_INDEX) with the
// index shift and offset; the errors. Every expectation was measured on Mesa
// 22.3 (llvmpipe) and the tests run on both.
#include <vector>

#include "stencil_context.h"

#ifndef GL_DEPTH_STENCIL
#define GL_DEPTH_STENCIL 0x84F9
#endif
#ifndef GL_UNSIGNED_INT_24_8
#define GL_UNSIGNED_INT_24_8 0x84FA
#endif

namespace glfx_test {
namespace {

// A stencil context (stencil_context.h) whose images are packed and
// unpacked a byte aligned.
class PixelsContext : public StencilContext {
 public:
  PixelsContext(int depth, int stencil) : StencilContext(depth, stencil) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }
  // The red byte of a pixel of the client buffer.
  int red(int x, int y) { return pixel(x, y)[0]; }
};

class StencilPixelsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(c_.ok());
    glClearStencil(0xa5);
    glClearDepth(0.75);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  }
  PixelsContext c_{24, 8};
};

// The stencil values of [x, x + w) x [y, y + h), rows bottom first, read
// without pixel transfer.
std::vector<int> Stencil(int x, int y, int w, int h) {
  std::vector<GLubyte> v(static_cast<size_t>(w) * h, 0xee);
  glReadPixels(x, y, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, v.data());
  return std::vector<int>(v.begin(), v.end());
}

// The 24-bit depth values of a rectangle, rows bottom first.
std::vector<unsigned> Depth(int x, int y, int w, int h) {
  std::vector<GLuint> v(static_cast<size_t>(w) * h, 0);
  glReadPixels(x, y, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, v.data());
  std::vector<unsigned> d;
  for (GLuint z : v) d.push_back(z >> 8);
  return d;
}

// A 4 x 4 stencil image: 0x10 + i, rows bottom first.
struct Image4x4 {
  GLubyte v[16];
  Image4x4() {
    for (int i = 0; i < 16; ++i) v[i] = static_cast<GLubyte>(0x10 + i);
  }
};

void DrawStencil(int x, int y, int w, int h, GLenum type, const void* p) {
  glWindowPos2i(x, y);
  glDrawPixels(w, h, GL_STENCIL_INDEX, type, p);
}

// ---- glDrawPixels(GL_STENCIL_INDEX) ---------------------------------------------

TEST_F(StencilPixelsTest, DrawLandsAtTheRoundedRasterPosition) {
  const Image4x4 img;
  glRasterPos2f(2.5f, 1.4f);  // lroundf: (3, 1)
  glDrawPixels(4, 4, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, img.v);
  EXPECT_NO_GL_ERROR();
  const int a = 0xa5;
  EXPECT_EQ(Stencil(2, 0, 6, 6), (std::vector<int>{a, a,    a,    a,    a,    a,  //
                                                   a, 0x10, 0x11, 0x12, 0x13, a,  //
                                                   a, 0x14, 0x15, 0x16, 0x17, a,  //
                                                   a, 0x18, 0x19, 0x1a, 0x1b, a,  //
                                                   a, 0x1c, 0x1d, 0x1e, 0x1f, a,  //
                                                   a, a,    a,    a,    a,    a}));
}

TEST_F(StencilPixelsTest, DrawIsZoomed) {
  const Image4x4 img;
  glPixelZoom(1.5f, 2.0f);
  DrawStencil(1, 1, 4, 4, GL_UNSIGNED_BYTE, img.v);
  const int a = 0xa5;
  const std::vector<int> s = Stencil(0, 0, 8, 10);
  // Measured on llvmpipe: columns 0 0 1 2 3 3 from x = 1, each row twice.
  const int cols[8] = {-1, 0, 0, 1, 2, 3, 3, -1};
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 8; ++x) {
      const int row = y >= 1 && y <= 8 ? (y - 1) / 2 : -1;
      const int want = row < 0 || cols[x] < 0 ? a : 0x10 + 4 * row + cols[x];
      EXPECT_EQ(s[y * 8 + x], want) << x << "," << y;
    }
  glClear(GL_STENCIL_BUFFER_BIT);
  glPixelZoom(-1, -1);  // mirrored, from (6, 6) down and left
  DrawStencil(6, 6, 4, 4, GL_UNSIGNED_BYTE, img.v);
  EXPECT_EQ(Stencil(2, 2, 4, 4), (std::vector<int>{0x1f, 0x1e, 0x1d, 0x1c, 0x1b, 0x1a, 0x19, 0x18,  //
                                                   0x17, 0x16, 0x15, 0x14, 0x13, 0x12, 0x11, 0x10}));
  EXPECT_EQ(Stencil(6, 6, 1, 1)[0], a);
}

TEST_F(StencilPixelsTest, DrawKeepsTheLowEightBitsOfEveryIndexType) {
  const GLbyte b[8] = {1, -1, 127, -128, 0x55, -2, 3, 4};
  DrawStencil(0, 0, 8, 1, GL_BYTE, b);
  EXPECT_EQ(Stencil(0, 0, 8, 1), (std::vector<int>{0x01, 0xff, 0x7f, 0x80, 0x55, 0xfe, 0x03, 0x04}));
  const GLshort s[8] = {1, -1, 0x1ff, -300, 0x7fff, 0x100, 0x2ab, 4};
  DrawStencil(0, 1, 8, 1, GL_SHORT, s);
  EXPECT_EQ(Stencil(0, 1, 8, 1), (std::vector<int>{0x01, 0xff, 0xff, 0xd4, 0xff, 0x00, 0xab, 0x04}));
  const GLushort us[8] = {1, 0xffff, 0x1ff, 0x8000, 0x80, 0x100, 0x2ab, 4};
  DrawStencil(0, 2, 8, 1, GL_UNSIGNED_SHORT, us);
  EXPECT_EQ(Stencil(0, 2, 8, 1), (std::vector<int>{0x01, 0xff, 0xff, 0x00, 0x80, 0x00, 0xab, 0x04}));
  const GLint i[8] = {1, -1, 0x1ff, -300, 0x7fffffff, 0x100, 0x12345678, 4};
  DrawStencil(0, 3, 8, 1, GL_INT, i);
  EXPECT_EQ(Stencil(0, 3, 8, 1), (std::vector<int>{0x01, 0xff, 0xff, 0xd4, 0xff, 0x00, 0x78, 0x04}));
  const GLuint ui[8] = {1, 0xffffffffu, 0x1ff, 0x80000000u, 0x7fffffff, 0x100, 0x12345678, 4};
  DrawStencil(0, 4, 8, 1, GL_UNSIGNED_INT, ui);
  EXPECT_EQ(Stencil(0, 4, 8, 1), (std::vector<int>{0x01, 0xff, 0xff, 0x00, 0xff, 0x00, 0x78, 0x04}));
  // Floats truncated toward zero, then the low bits; far-off ones and NaN 0.
  const GLfloat f[16] = {1.4f,  1.5f,   2.5f, -1.0f,    255.9f,   256.0f, 300.0f, 0.6f,
                         1e10f, -1e10f, NAN,  65535.5f, 65536.0f, 3.99f,  -0.5f,  7.5f};
  DrawStencil(0, 5, 8, 2, GL_FLOAT, f);
  EXPECT_EQ(Stencil(0, 5, 8, 2), (std::vector<int>{0x01, 0x01, 0x02, 0xff, 0xff, 0x00, 0x2c, 0x00,  //
                                                   0x00, 0x00, 0x00, 0xff, 0x00, 0x03, 0x00, 0x07}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(StencilPixelsTest, DrawUnpacksRowLengthSkipsAndSwappedBytes) {
  const GLushort us[12] = {0, 0, 0, 0, 0x0102, 0x0304, 0, 0, 0x0506, 0x0708, 0, 0};
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  DrawStencil(1, 1, 2, 2, GL_UNSIGNED_SHORT, us);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  DrawStencil(5, 1, 2, 2, GL_UNSIGNED_SHORT, us);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  EXPECT_EQ(Stencil(1, 1, 2, 2), (std::vector<int>{0x01, 0x03, 0x05, 0x07}));
  EXPECT_EQ(Stencil(5, 1, 2, 2), (std::vector<int>{0x04, 0x00, 0x08, 0x00}));
}

TEST_F(StencilPixelsTest, DrawTakesNoIndexShiftOffsetOrMap) {
  // Mesa stores the image with the pixel transfer state cleared (GL 2.1
  // §3.6.5 would shift, offset and map it).
  const Image4x4 img;
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  DrawStencil(1, 1, 4, 1, GL_UNSIGNED_BYTE, img.v);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{0x10, 0x11, 0x12, 0x13}));
}

TEST_F(StencilPixelsTest, ReadMapsThroughSToS) {
  // glReadPixels applies GL_MAP_STENCIL after the shift and offset: the
  // index masked by the map's size - 1, the entry cut to a byte.
  const Image4x4 img;  // 0x10 .. 0x13 in its first row
  DrawStencil(1, 1, 4, 1, GL_UNSIGNED_BYTE, img.v);
  const GLfloat map[4] = {5, 300, -4, 9};
  glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 4, map);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{5, 300 & 0xff, 252, 9}));
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{300 & 0xff, 252, 9, 5}));
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{0x10, 0x11, 0x12, 0x13}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(StencilPixelsTest, DrawWritesThroughTheFrontWriteMask) {
  const Image4x4 img;
  glStencilMaskSeparate(GL_FRONT, 0x0f);
  glStencilMaskSeparate(GL_BACK, 0xf0);
  DrawStencil(1, 1, 4, 1, GL_UNSIGNED_BYTE, img.v);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{0xa0, 0xa1, 0xa2, 0xa3}));
  glPixelZoom(-1, 1);  // the quad faces the other way: still the front mask
  DrawStencil(5, 2, 4, 1, GL_UNSIGNED_BYTE, img.v);
  EXPECT_EQ(Stencil(1, 2, 4, 1), (std::vector<int>{0xa3, 0xa2, 0xa1, 0xa0}));
  glStencilMaskSeparate(GL_FRONT, 0);
  glStencilMaskSeparate(GL_BACK, 0xff);
  glPixelZoom(1, 1);
  DrawStencil(1, 3, 4, 1, GL_UNSIGNED_BYTE, img.v);
  EXPECT_EQ(Stencil(1, 3, 4, 1), (std::vector<int>{0xa5, 0xa5, 0xa5, 0xa5}));
}

TEST_F(StencilPixelsTest, DrawIsCutByTheScissorAndTheBuffer) {
  const Image4x4 img;
  glScissor(2, 2, 2, 10);
  glEnable(GL_SCISSOR_TEST);
  DrawStencil(1, 1, 4, 4, GL_UNSIGNED_BYTE, img.v);
  const int a = 0xa5;
  EXPECT_EQ(Stencil(1, 1, 4, 4), (std::vector<int>{a, a, a, a,        //
                                                   a, 0x15, 0x16, a,  //
                                                   a, 0x19, 0x1a, a,  //
                                                   a, 0x1d, 0x1e, a}));
  glClear(GL_STENCIL_BUFFER_BIT);
  glPixelZoom(2, 2);
  DrawStencil(1, 1, 4, 4, GL_UNSIGNED_BYTE, img.v);
  EXPECT_EQ(Stencil(2, 1, 2, 9), (std::vector<int>{a, a, 0x10, 0x11, 0x14, 0x15, 0x14, 0x15, 0x18, 0x19, 0x18,
                                                   0x19, 0x1c, 0x1d, 0x1c, 0x1d, a, a}));
  EXPECT_EQ(Stencil(1, 3, 1, 1)[0], a);
  EXPECT_EQ(Stencil(4, 3, 1, 1)[0], a);
  glDisable(GL_SCISSOR_TEST);
  glPixelZoom(1, 1);
  glClear(GL_STENCIL_BUFFER_BIT);
  DrawStencil(-2, -1, 4, 4, GL_UNSIGNED_BYTE, img.v);  // a window position outside the buffer
  EXPECT_EQ(Stencil(0, 0, 3, 3), (std::vector<int>{0x16, 0x17, a, 0x1a, 0x1b, a, 0x1e, 0x1f, a}));
}

TEST_F(StencilPixelsTest, DrawIgnoresTheTestsAndWritesNoColour) {
  const Image4x4 img;
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0xff);
  glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_NEVER, 0);
  glColor3f(1, 1, 1);
  DrawStencil(1, 1, 4, 1, GL_UNSIGNED_BYTE, img.v);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{0x10, 0x11, 0x12, 0x13}));
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_ALPHA_TEST);
  EXPECT_EQ(c_.red(2, 1), 0);
  EXPECT_EQ(Depth(2, 1, 1, 1)[0], 0xbfffffu);
}

TEST_F(StencilPixelsTest, DisplayListKeepsTheStencilImageOfCompileTime) {
  Image4x4 img;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  DrawStencil(1, 1, 4, 1, GL_UNSIGNED_BYTE, img.v);
  glEndList();
  img.v[0] = 0x77;
  glCallList(list);
  glDeleteLists(list, 1);
  EXPECT_EQ(Stencil(1, 1, 4, 1), (std::vector<int>{0x10, 0x11, 0x12, 0x13}));
}

TEST_F(StencilPixelsTest, BitmapIndicesAreZeroOrOne) {
  // Mesa 22.3 prints "Unsupported format/type" without end for
  // GL_STENCIL_INDEX / GL_BITMAP; libglfixed draws the bits (§3.6.4).
  GLFX_SKIP_ON_MESA("glDrawPixels(GL_STENCIL_INDEX, GL_BITMAP) never returns");
  const GLubyte bits[2] = {0xa5, 0x3c};
  DrawStencil(1, 1, 8, 2, GL_BITMAP, bits);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Stencil(1, 1, 8, 2), (std::vector<int>{1, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 0, 0}));
}

// ---- glDrawPixels(GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8) --------------------------

TEST_F(StencilPixelsTest, DepthStencilDrawWritesBothWhateverTheDepthTest) {
  const GLuint ds[4] = {0x00000011, 0x80000022, 0xffffff33, 0x40000044};
  glColor3f(1, 1, 1);
  glWindowPos2i(1, 1);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);  // the depth test off
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Depth(1, 1, 2, 2), (std::vector<unsigned>{0x000000, 0x800000, 0xffffff, 0x400000}));
  EXPECT_EQ(Stencil(1, 1, 2, 2), (std::vector<int>{0x11, 0x22, 0x33, 0x44}));
  EXPECT_EQ(c_.red(1, 1), 0);
  // The depth and stencil tests do not apply; the stencil mask does.
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0);
  glStencilMask(0x0f);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  glStencilMask(0xff);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(Depth(1, 1, 2, 2), (std::vector<unsigned>{0x000000, 0x800000, 0xffffff, 0x400000}));
  EXPECT_EQ(Stencil(1, 1, 2, 2), (std::vector<int>{0xa1, 0xa2, 0xa3, 0xa4}));
  // The depth mask does; depth scale and bias, index shift and offset do not.
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  glDepthMask(GL_TRUE);
  EXPECT_EQ(Depth(1, 1, 2, 2), (std::vector<unsigned>{0xbfffff, 0xbfffff, 0xbfffff, 0xbfffff}));
  EXPECT_EQ(Stencil(1, 1, 2, 2), (std::vector<int>{0x11, 0x22, 0x33, 0x44}));
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  glPixelTransferf(GL_DEPTH_SCALE, 1);
  glPixelTransferf(GL_DEPTH_BIAS, 0);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  EXPECT_EQ(Depth(1, 1, 2, 2), (std::vector<unsigned>{0x000000, 0x800000, 0xffffff, 0x400000}));
  EXPECT_EQ(Stencil(1, 1, 2, 2), (std::vector<int>{0x11, 0x22, 0x33, 0x44}));
}

TEST_F(StencilPixelsTest, DepthStencilDrawIsZoomedAndScissored) {
  const GLuint ds[4] = {0x00000011, 0x80000022, 0xffffff33, 0x40000044};
  glWindowPos2i(1, 1);
  glPixelZoom(2, 1.5f);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  glPixelZoom(1, 1);
  const int a = 0xa5;
  EXPECT_EQ(Stencil(0, 0, 6, 5), (std::vector<int>{a, a,    a,    a,    a,    a,  //
                                                   a, 0x11, 0x11, 0x22, 0x22, a,  //
                                                   a, 0x33, 0x33, 0x44, 0x44, a,  //
                                                   a, 0x33, 0x33, 0x44, 0x44, a,  //
                                                   a, a,    a,    a,    a,    a}));
  EXPECT_EQ(Depth(1, 3, 4, 1), (std::vector<unsigned>{0xffffff, 0xffffff, 0x400000, 0x400000}));
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glScissor(2, 0, 1, 9);
  glEnable(GL_SCISSOR_TEST);
  glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(Stencil(1, 1, 2, 2), (std::vector<int>{a, 0x22, a, 0x44}));
  EXPECT_EQ(Depth(1, 1, 2, 2), (std::vector<unsigned>{0xbfffff, 0x800000, 0xbfffff, 0x400000}));
}

// ---- glCopyPixels(GL_STENCIL) ------------------------------------------------------

// The stencil buffer's [0, 8) x [0, 8): 0x10 + x + 8 y.
void FillStencil() {
  GLubyte img[64];
  for (int i = 0; i < 64; ++i) img[i] = static_cast<GLubyte>(0x10 + i);
  glClear(GL_STENCIL_BUFFER_BIT);
  DrawStencil(0, 0, 8, 8, GL_UNSIGNED_BYTE, img);
}

TEST_F(StencilPixelsTest, CopyStencilTakesTheWriteMaskAndScissorButNoTransfer) {
  FillStencil();
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_STENCIL);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Stencil(10, 1, 3, 2), (std::vector<int>{0x19, 0x1a, 0x1b, 0x21, 0x22, 0x23}));
  FillStencil();
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_STENCIL);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  EXPECT_EQ(Stencil(10, 1, 3, 2), (std::vector<int>{0x19, 0x1a, 0x1b, 0x21, 0x22, 0x23}));
  FillStencil();
  glStencilMask(0x0f);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_STENCIL);
  glStencilMask(0xff);
  EXPECT_EQ(Stencil(10, 1, 3, 2), (std::vector<int>{0xa9, 0xaa, 0xab, 0xa1, 0xa2, 0xa3}));
  FillStencil();
  glScissor(11, 0, 1, 10);
  glEnable(GL_SCISSOR_TEST);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_STENCIL);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(Stencil(10, 1, 3, 2), (std::vector<int>{0xa5, 0x1a, 0xa5, 0xa5, 0x22, 0xa5}));
  // The stencil and depth tests do not apply.
  FillStencil();
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_STENCIL);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(Stencil(10, 1, 3, 2), (std::vector<int>{0x19, 0x1a, 0x1b, 0x21, 0x22, 0x23}));
}

TEST_F(StencilPixelsTest, CopyStencilIsZoomed) {
  FillStencil();
  glPixelZoom(2, 1);
  glStencilMask(0x0f);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_STENCIL);
  glStencilMask(0xff);
  glPixelZoom(1, 1);
  EXPECT_EQ(Stencil(10, 1, 6, 2), (std::vector<int>{0xa9, 0xa9, 0xaa, 0xaa, 0xab, 0xab,  //
                                                    0xa1, 0xa1, 0xa2, 0xa2, 0xa3, 0xa3}));
  EXPECT_EQ(Stencil(16, 1, 1, 1)[0], 0xa5);
}

TEST_F(StencilPixelsTest, OverlappingStencilCopyReadsTheSourceFirst) {
  FillStencil();
  glWindowPos2i(2, 2);
  glCopyPixels(1, 1, 4, 4, GL_STENCIL);
  const std::vector<int> s = Stencil(0, 0, 8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool inside = x >= 2 && x < 6 && y >= 2 && y < 6;
      const int want = inside ? 0x10 + (x - 1) + 8 * (y - 1) : 0x10 + x + 8 * y;
      EXPECT_EQ(s[y * 8 + x], want) << x << "," << y;
    }
}

TEST_F(StencilPixelsTest, StencilCopiedFromOutsideTheBufferIsZero) {
  FillStencil();
  glWindowPos2i(3, 0);
  glCopyPixels(-2, -1, 4, 4, GL_STENCIL);
  EXPECT_EQ(Stencil(3, 0, 4, 4), (std::vector<int>{0, 0, 0, 0,        //
                                                   0, 0, 0x10, 0x11,  //
                                                   0, 0, 0x18, 0x19,  //
                                                   0, 0, 0x20, 0x21}));
  FillStencil();
  glPixelZoom(2, 2);
  glWindowPos2i(20, 20);
  glCopyPixels(6, 6, 4, 4, GL_STENCIL);  // [6, 8) holds the image, [8, 10) the clear value
  glPixelZoom(1, 1);
  EXPECT_EQ(Stencil(20, 20, 2, 2), (std::vector<int>{0x46, 0x46, 0x46, 0x46}));
  EXPECT_EQ(Stencil(24, 24, 2, 2), (std::vector<int>{0xa5, 0xa5, 0xa5, 0xa5}));
  glWindowPos2i(40, 40);
  glCopyPixels(62, 62, 4, 4, GL_STENCIL);
  EXPECT_EQ(Stencil(40, 40, 4, 4),
            (std::vector<int>{0xa5, 0xa5, 0, 0, 0xa5, 0xa5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
}

TEST(StencilPixelsBufferTest, StencilWithoutDepthDrawsAndCopies) {
  PixelsContext c(0, 8);
  ASSERT_TRUE(c.ok());
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  const GLubyte v = 7;
  DrawStencil(1, 1, 1, 1, GL_UNSIGNED_BYTE, &v);
  glWindowPos2i(0, 0);
  glCopyPixels(1, 1, 1, 1, GL_STENCIL);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Stencil(0, 0, 3, 2), (std::vector<int>{7, 0, 0, 0, 7, 0}));
  glPixelZoom(2, 2);
  glWindowPos2i(3, 0);
  glCopyPixels(1, 1, 1, 1, GL_STENCIL);
  EXPECT_EQ(Stencil(3, 0, 3, 2), (std::vector<int>{7, 7, 0, 7, 7, 0}));
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLuint ds = 0;
  glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

// ---- glCopyPixels(GL_DEPTH) and (GL_DEPTH_STENCIL) -----------------------------------

// The depth buffer's [0, 8) x [0, 8): (x + 8 y) / 64, drawn with the colour
// masked; returns the depths stored there (rows bottom first), which the
// copies must carry unchanged.
std::vector<unsigned> FillDepth() {
  GLfloat z[64];
  for (int i = 0; i < 64; ++i) z[i] = static_cast<GLfloat>(i) / 64.0f;
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glWindowPos2i(0, 0);
  glDrawPixels(8, 8, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  return Depth(0, 0, 8, 8);
}

TEST_F(StencilPixelsTest, CopyDepthGoesThroughTheDepthTestWithTheCurrentColour) {
  const std::vector<unsigned> z = FillDepth();
  auto FilledDepth = [&](int x, int y) { return z[y * 8 + x]; };
  EXPECT_EQ(FilledDepth(1, 1), 0x240000u);
  // The depth test off: no depth written, but the colour is.
  glColor4f(1, 0.5f, 0.25f, 1);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_DEPTH);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Depth(10, 1, 3, 1), (std::vector<unsigned>{0xbfffff, 0xbfffff, 0xbfffff}));
  EXPECT_EQ(c_.red(10, 1), 255);
  EXPECT_EQ(c_.red(13, 1), 0);
  // GL_ALWAYS: the source depths; the colour the current one, not the raster colour.
  FillDepth();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor4f(0.2f, 0.4f, 0.6f, 1);
  glWindowPos2i(10, 1);
  glColor4f(0.8f, 0.4f, 0.6f, 1);
  glCopyPixels(1, 1, 3, 2, GL_DEPTH);
  EXPECT_EQ(Depth(10, 1, 3, 2),
            (std::vector<unsigned>{FilledDepth(1, 1), FilledDepth(2, 1), FilledDepth(3, 1), FilledDepth(1, 2),
                                   FilledDepth(2, 2), FilledDepth(3, 2)}));
  EXPECT_EQ(c_.red(11, 2), 204);
  // GL_GREATER against the destination.
  FillDepth();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glWindowPos2i(1, 1);
  glCopyPixels(2, 1, 3, 2, GL_DEPTH);
  EXPECT_EQ(Depth(0, 1, 6, 1),
            (std::vector<unsigned>{FilledDepth(0, 1), FilledDepth(2, 1), FilledDepth(3, 1), FilledDepth(4, 1),
                                   FilledDepth(4, 1), FilledDepth(5, 1)}));
  EXPECT_EQ(c_.red(1, 1), 204);
  glDisable(GL_DEPTH_TEST);
}

TEST_F(StencilPixelsTest, CopyDepthTakesNoScaleOrBiasButTheMaskAndTheStencil) {
  const std::vector<unsigned> z = FillDepth();
  auto FilledDepth = [&](int x, int y) { return z[y * 8 + x]; };
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 1, GL_DEPTH);
  glPixelTransferf(GL_DEPTH_SCALE, 1);
  glPixelTransferf(GL_DEPTH_BIAS, 0);
  EXPECT_EQ(Depth(10, 1, 3, 1),
            (std::vector<unsigned>{FilledDepth(1, 1), FilledDepth(2, 1), FilledDepth(3, 1)}));
  FillDepth();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_FALSE);
  glColor3f(1, 1, 1);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 1, GL_DEPTH);
  glDepthMask(GL_TRUE);
  EXPECT_EQ(Depth(10, 1, 3, 1), (std::vector<unsigned>{0xbfffff, 0xbfffff, 0xbfffff}));
  EXPECT_EQ(c_.red(10, 1), 255);
  FillDepth();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0xa5, 0xff);
  glStencilOp(GL_KEEP, GL_INCR, GL_ZERO);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 1, GL_DEPTH);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(Stencil(9, 1, 5, 1), (std::vector<int>{0xa5, 0, 0, 0, 0xa5}));
}

TEST_F(StencilPixelsTest, CopyDepthZoomedOverlappingAndFromOutside) {
  const std::vector<unsigned> z = FillDepth();
  auto FilledDepth = [&](int x, int y) { return z[y * 8 + x]; };
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glPixelZoom(2, 1);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 1, GL_DEPTH);
  glPixelZoom(1, 1);
  EXPECT_EQ(Depth(10, 1, 6, 1),
            (std::vector<unsigned>{FilledDepth(1, 1), FilledDepth(1, 1), FilledDepth(2, 1), FilledDepth(2, 1),
                                   FilledDepth(3, 1), FilledDepth(3, 1)}));
  FillDepth();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glWindowPos2i(2, 2);
  glCopyPixels(1, 1, 4, 4, GL_DEPTH);
  const std::vector<unsigned> d = Depth(0, 0, 8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool inside = x >= 2 && x < 6 && y >= 2 && y < 6;
      EXPECT_EQ(d[y * 8 + x], inside ? FilledDepth(x - 1, y - 1) : FilledDepth(x, y)) << x << "," << y;
    }
  FillDepth();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glWindowPos2i(3, 0);
  glCopyPixels(-2, -1, 4, 4, GL_DEPTH);
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(Depth(3, 0, 4, 2),
            (std::vector<unsigned>{0, 0, 0, 0, 0, 0, FilledDepth(0, 0), FilledDepth(1, 0)}));
}

TEST_F(StencilPixelsTest, CopyDepthStencilWritesBothAndNoColour) {
  const std::vector<unsigned> z = FillDepth();
  auto FilledDepth = [&](int x, int y) { return z[y * 8 + x]; };
  FillStencil();
  glColor3f(1, 1, 1);
  glWindowPos2i(10, 1);
  glCopyPixels(1, 1, 3, 2, GL_DEPTH_STENCIL);  // the depth test off
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Depth(10, 1, 3, 1),
            (std::vector<unsigned>{FilledDepth(1, 1), FilledDepth(2, 1), FilledDepth(3, 1)}));
  EXPECT_EQ(Stencil(10, 1, 3, 2), (std::vector<int>{0x19, 0x1a, 0x1b, 0x21, 0x22, 0x23}));
  EXPECT_EQ(c_.red(10, 1), 0);
}

// ---- glReadPixels(GL_STENCIL_INDEX) with the index shift and offset ---------------

TEST_F(StencilPixelsTest, ReadShiftsAndOffsetsOnThirtyTwoBitsKeepingEight) {
  glClearStencil(0x81);
  glClear(GL_STENCIL_BUFFER_BIT);
  struct Case {
    int shift, offset, value;
  };
  // The count taken modulo 32 (x86), the result cut to 8 bits.
  const Case cases[] = {{0, 3, 132},  {0, -1, 128},  {0, -200, 185}, {0, 4096, 129},
                        {1, 3, 5},    {7, -1, 127},  {8, -1, 255},   {31, 3, 3},
                        {32, 3, 132}, {33, 3, 5},    {40, -1, 255},  {-1, 3, 67},
                        {-7, 0, 1},   {-8, -1, 255}, {-32, 0, 129},  {-33, -200, 120}};
  for (const Case& k : cases) {
    glPixelTransferi(GL_INDEX_SHIFT, k.shift);
    glPixelTransferi(GL_INDEX_OFFSET, k.offset);
    const StencilInEveryType v = ReadStencilInEveryType(0, 0);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(v.ub, k.value) << k.shift << " " << k.offset;
    EXPECT_EQ(v.b, k.value & 0x7f) << k.shift << " " << k.offset;  // GL_BYTE: 7 bits
    EXPECT_EQ(v.us, k.value) << k.shift << " " << k.offset;
    EXPECT_EQ(v.s, k.value) << k.shift << " " << k.offset;
    EXPECT_EQ(v.ui, static_cast<GLuint>(k.value)) << k.shift << " " << k.offset;
    EXPECT_EQ(v.i, k.value) << k.shift << " " << k.offset;
    EXPECT_EQ(v.f, static_cast<GLfloat>(k.value)) << k.shift << " " << k.offset;
  }
  // GL_DEPTH_STENCIL reads take the same stencil transfer.
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  GLuint ds = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_EQ(ds, 0x80000005u);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
}

// GL_DEPTH_SCALE and GL_DEPTH_BIAS (§3.6.5) on depth reads, with Mesa's
// conversions from the scaled float.
TEST_F(StencilPixelsTest, DepthReadsTakeTheDepthScaleAndBias) {
  glClearDepth(0.5);  // stored 0x800000
  glClearStencil(0x21);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  GLubyte ub = 0;
  GLbyte b = 0;
  GLshort s = 0;
  GLushort us = 0;
  GLint i = 0;
  GLuint ui = 0, ds = 0;
  GLfloat f = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, &ub);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_BYTE, &b);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_SHORT, &s);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &us);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_INT, &i);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &ui);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(ub, 63);
  EXPECT_EQ(b, 31);
  EXPECT_EQ(s, 8191);
  EXPECT_EQ(us, 0x4000);
  EXPECT_EQ(i, 536870975);
  EXPECT_EQ(ui, 0x4000007fu);
  EXPECT_FLOAT_EQ(f, 0.25000003f);
  EXPECT_EQ(ds, 0x40000021u);
  // Clamped to [0, 1]; 1.0 scaled by 0.5 truncates to 0x7fffff in 24 bits.
  glClearDepth(1);
  glClear(GL_DEPTH_BUFFER_BIT);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_EQ(ds, 0x7fffff21u);
  glPixelTransferf(GL_DEPTH_SCALE, 2.0f);
  glPixelTransferf(GL_DEPTH_BIAS, -0.3f);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &ui);
  EXPECT_EQ(ui, 0xffffffffu);
  glPixelTransferf(GL_DEPTH_SCALE, 0.7f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.1f);
  glClearDepth(0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, &ub);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &us);
  EXPECT_EQ(ub, 25);      // 25.5 truncated
  EXPECT_EQ(us, 0x199a);  // 6553.5 rounded to even
  glPixelTransferf(GL_DEPTH_SCALE, 1);
  glPixelTransferf(GL_DEPTH_BIAS, 0);
}

// ---- errors ---------------------------------------------------------------------

TEST_F(StencilPixelsTest, FormatAndTypeErrors) {
  GLuint v = 1;
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT_5_6_5, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_STENCIL_INDEX, 0x1234, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawPixels(1, 1, 0x8227 /* GL_RG */, GL_UNSIGNED_SHORT_5_6_5, &v);  // piglit draw-pixels
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL_INDEX);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glCopyPixels(0, 0, -1, 1, GL_STENCIL);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawPixels(-1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(Stencil(0, 0, 1, 1)[0], 0xa5);
}

TEST(StencilPixelsBufferTest, WithoutAStencilBufferIsInvalidOperation) {
  PixelsContext c(24, 0);
  ASSERT_TRUE(c.ok());
  GLuint v = 1;
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);  // a depth buffer: fine
  EXPECT_NO_GL_ERROR();
}

TEST(StencilPixelsBufferTest, DepthCopyOnASixteenBitBufferKeepsTheValues) {
  PixelsContext c(16, 0);
  ASSERT_TRUE(c.ok());
  ASSERT_EQ(GetInt(GL_DEPTH_BITS), 16);
  GLushort z[8];
  for (int i = 0; i < 8; ++i) z[i] = static_cast<GLushort>(1000 + 7919 * i);
  glClearDepth(1);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glWindowPos2i(0, 0);
  glDrawPixels(8, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, z);
  GLushort before[8], after[8];
  glReadPixels(0, 0, 8, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, before);
  glPixelZoom(1, 2);
  glWindowPos2i(0, 4);
  glCopyPixels(0, 0, 8, 1, GL_DEPTH);
  glPixelZoom(1, 1);
  glDisable(GL_DEPTH_TEST);
  EXPECT_NO_GL_ERROR();
  for (int row = 4; row < 6; ++row) {
    glReadPixels(0, row, 8, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, after);
    for (int i = 0; i < 8; ++i) EXPECT_EQ(after[i], before[i]) << i << "," << row;
  }
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

}  // namespace
}  // namespace glfx_test
