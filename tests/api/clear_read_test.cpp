// glClear and glReadPixels (GL 2.1 §4.2.3, §4.3.2), the client colour buffer
// of every OSMesa pixel format, and the OSMesa entry points.
#include <string>

#include "gl_test_fixture.h"

#ifndef GL_PACK_INVERT_MESA
#define GL_PACK_INVERT_MESA 0x8758
#endif

namespace glfx_test {
namespace {

using ClearReadTest = GLTest;

// Float to an 8-bit colour component: GL 2.1 §2.14.9 asks for the nearest
// value; the reference (llvmpipe) rounds a single-precision v * 255 to nearest
// even, so 0.3 gives 76.
unsigned char ToUnorm8(float v) {
  v = v < 0 ? 0 : (v > 1 ? 1 : v);
  return static_cast<unsigned char>(std::nearbyint(v * 255.0f));
}

TEST_F(ClearReadTest, ClearColorRounding) {
  EXPECT_EQ(ToUnorm8(0.3f), 76);  // the rounding rule this test relies on
  const float values[] = {0.0f,  1.0f,  0.3f,  0.5f,  0.2f,       0.7f,         0.1f,     0.9f,
                          0.25f, 0.75f, 0.01f, 0.99f, 1.0f / 255, 127.5f / 255, 0.50196f, 0.6f};
  const size_t n = sizeof values / sizeof values[0];
  for (size_t i = 0; i < n; ++i) {
    float c[4];
    for (size_t k = 0; k < 4; ++k) c[k] = values[(i + k) % n];
    SCOPED_TRACE(::testing::Message()
                 << "clear colour " << c[0] << " " << c[1] << " " << c[2] << " " << c[3]);
    glClearColor(c[0], c[1], c[2], c[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char out[4] = {0, 0, 0, 0};
    glReadPixels(kWidth / 2, kHeight / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(out[k], ToUnorm8(c[k])) << "channel " << k << " of glReadPixels";
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(pixels()[k], ToUnorm8(c[k])) << "channel " << k << " of the client buffer";
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClearReadTest, ClearColorIsClamped) {
  glClearColor(-0.5f, 1.5f, 0.3f, 7.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const unsigned char* p = pixels();
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 255);
  EXPECT_EQ(p[2], 76);
  EXPECT_EQ(p[3], 255);
}

TEST_F(ClearReadTest, ClearFillsTheWholeClientBuffer) {
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const unsigned char* p = pixels() + 4 * i;
    ASSERT_TRUE(p[0] == 51 && p[1] == 102 && p[2] == 153 && p[3] == 204)
        << "pixel " << i << ": " << int(p[0]) << " " << int(p[1]) << " " << int(p[2]) << " " << int(p[3]);
  }
}

// §4.2.3: the viewport does not limit glClear.
TEST_F(ClearReadTest, ClearIgnoresTheViewport) {
  glViewport(10, 10, 5, 5);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (int i = 0; i < kWidth * kHeight * 4; ++i) ASSERT_EQ(pixels()[i], 255) << "byte " << i;
}

TEST_F(ClearReadTest, ReadPixelsRgbaBgraRgb) {
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  std::vector<unsigned char> rgba(kWidth * kHeight * 4, 0);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < kWidth * kHeight; ++i) {
    ASSERT_TRUE(rgba[4 * i] == 51 && rgba[4 * i + 1] == 102 && rgba[4 * i + 2] == 153 &&
                rgba[4 * i + 3] == 204)
        << "GL_RGBA pixel " << i;
  }
  std::vector<unsigned char> bgra(kWidth * kHeight * 4, 0);
  glReadPixels(0, 0, kWidth, kHeight, GL_BGRA, GL_UNSIGNED_BYTE, bgra.data());
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < kWidth * kHeight; ++i) {
    ASSERT_TRUE(bgra[4 * i] == 153 && bgra[4 * i + 1] == 102 && bgra[4 * i + 2] == 51 &&
                bgra[4 * i + 3] == 204)
        << "GL_BGRA pixel " << i;
  }
  // A 4x4 block at (10, 20): 12-byte rows, already 4-aligned.
  unsigned char rgb[4 * 4 * 3 + 8];
  std::memset(rgb, 0x3C, sizeof rgb);
  glReadPixels(10, 20, 4, 4, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < 16; ++i) {
    ASSERT_TRUE(rgb[3 * i] == 51 && rgb[3 * i + 1] == 102 && rgb[3 * i + 2] == 153) << "GL_RGB pixel " << i;
  }
  for (size_t i = 48; i < sizeof rgb; ++i) EXPECT_EQ(rgb[i], 0x3C) << "wrote past the image, byte " << i;
}

TEST_F(ClearReadTest, ReadPixelsRgbaFloat) {
  glClearColor(0.3f, 1.0f, 0.0f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  GLfloat out[4] = {-1, -1, -1, -1};
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_FLOAT, out);
  EXPECT_NO_GL_ERROR();
  EXPECT_NEAR(out[0], 76 / 255.0, 1e-6);
  EXPECT_NEAR(out[1], 1.0, 1e-6);
  EXPECT_NEAR(out[2], 0.0, 1e-6);
  EXPECT_NEAR(out[3], 128 / 255.0, 1e-6);
}

// GL_PACK_ALIGNMENT (§4.3.2, §3.6.4): each row starts at a multiple of the
// alignment; the padding bytes are not written.
TEST_F(ClearReadTest, PackAlignment) {
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 4);
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  const int w = 5, h = 3;  // GL_RGB rows of 15 bytes
  for (int alignment : {1, 2, 4, 8}) {
    SCOPED_TRACE(::testing::Message() << "alignment " << alignment);
    glPixelStorei(GL_PACK_ALIGNMENT, alignment);
    EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), alignment);
    const int stride = (w * 3 + alignment - 1) / alignment * alignment;
    std::vector<unsigned char> out(stride * h + 16, 0x3C);
    glReadPixels(7, 9, w, h, GL_RGB, GL_UNSIGNED_BYTE, out.data());
    EXPECT_NO_GL_ERROR();
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const unsigned char* p = out.data() + y * stride + 3 * x;
        EXPECT_TRUE(p[0] == 51 && p[1] == 102 && p[2] == 153) << "pixel " << x << "," << y;
      }
      for (int b = w * 3; b < stride && y + 1 < h; ++b)
        EXPECT_EQ(out[y * stride + b], 0x3C) << "padding written";
    }
    for (size_t b = (h - 1) * stride + w * 3; b < out.size(); ++b)
      EXPECT_EQ(out[b], 0x3C) << "wrote past the image";
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 3);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glPixelStorei(GL_PACK_ALIGNMENT, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 8);
}

// 24-bit depth: a value d reads back as d to within one step of 2^24 - 1.
TEST_F(ClearReadTest, ReadDepthFloatAndUnsignedInt) {
  const double values[] = {1.0, 0.0, 0.5, 0.25, 0.75, 0.1};
  for (double d : values) {
    SCOPED_TRACE(::testing::Message() << "clear depth " << d);
    glClearDepth(d);
    glClear(GL_DEPTH_BUFFER_BIT);
    GLfloat f[4] = {-1, -1, -1, -1};
    glReadPixels(5, 6, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    EXPECT_NO_GL_ERROR();
    for (GLfloat v : f) EXPECT_NEAR(v, d, 1.0 / 16777215.0 + 1e-7);
    GLuint u[4] = {1, 1, 1, 1};
    glReadPixels(5, 6, 2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, u);
    EXPECT_NO_GL_ERROR();
    for (GLuint v : u) {
      if (d == 1.0) {
        EXPECT_EQ(v, 0xFFFFFFFFu) << "1.0 is the largest value";
      } else if (d == 0.0) {
        EXPECT_EQ(v, 0u);
      } else {
        EXPECT_NEAR(static_cast<double>(v), d * 4294967295.0, 4294967296.0 / 16777215.0 + 1.0);
      }
    }
    GLushort s[4] = {1, 1, 1, 1};
    glReadPixels(5, 6, 2, 2, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, s);
    EXPECT_NO_GL_ERROR();
    for (GLushort v : s) EXPECT_NEAR(v, d * 65535.0, 1.0);
  }
}

TEST_F(ClearReadTest, ClearBitsAreIndependent) {
  glClearColor(1, 0, 0, 1);
  glClearDepth(0.25);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glClearColor(0, 1, 0, 1);
  glClearDepth(0.75);
  glClear(GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(pixels()[0], 255) << "a depth clear touched colour";
  EXPECT_EQ(pixels()[1], 0);
  GLfloat d = -1;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  EXPECT_NEAR(d, 0.75, 1e-6);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(pixels()[0], 0);
  EXPECT_EQ(pixels()[1], 255);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  EXPECT_NEAR(d, 0.75, 1e-6) << "a colour clear touched depth";
  EXPECT_NO_GL_ERROR();
}

// §4.2.3: glClear honours the depth write mask.
TEST_F(ClearReadTest, DepthMaskBlocksTheDepthClear) {
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  GLfloat d = -1;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
  EXPECT_NEAR(d, 0.25, 1e-6);
  EXPECT_NO_GL_ERROR();
}

// Window row 0 is the bottom row, and by default (OSMESA_Y_UP) also the first
// row of the client buffer. A quad over the lower half shows both.
TEST_F(ClearReadTest, RowZeroIsTheBottomRow) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor4f(1, 1, 1, 1);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 0);
  glVertex2f(-1, 0);
  glEnd();
  glFinish();
  EXPECT_NO_GL_ERROR();
  unsigned char low[4] = {0, 0, 0, 0}, high[4] = {9, 9, 9, 9};
  glReadPixels(3, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, low);
  glReadPixels(3, kHeight - 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, high);
  EXPECT_EQ(low[0], 255);
  EXPECT_EQ(high[0], 0);
  for (int y = 0; y < kHeight; ++y) {
    const unsigned char* row = pixels() + y * kWidth * 4;
    EXPECT_EQ(row[4 * 20], y < kHeight / 2 ? 255 : 0) << "client buffer row " << y;
  }
}

// GL_MESA_pack_invert: glReadPixels and glGetTexImage write the top row
// first; the value is kept as given and saved by the client attribute stack.
TEST_F(ClearReadTest, PackInvertWritesTheTopRowFirst) {
  ASSERT_NE(std::string(reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS))).find("GL_MESA_pack_invert "),
            std::string::npos);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor4f(1, 1, 1, 1);
  glRectf(-1, -1, 1, -1 + 2.0f / kHeight);  // row 0 only
  glPixelStorei(GL_PACK_INVERT_MESA, 5);
  GLint invert = 0;
  glGetIntegerv(GL_PACK_INVERT_MESA, &invert);
  EXPECT_EQ(invert, 5);
  unsigned char rows[3][4] = {};
  glReadPixels(0, 0, 1, 3, GL_RGBA, GL_UNSIGNED_BYTE, rows);
  EXPECT_EQ(rows[0][0], 0);
  EXPECT_EQ(rows[2][0], 255);  // window row 0, written last
  const unsigned char texels[2][2][4] = {{{10, 0, 0, 255}, {10, 0, 0, 255}}, {{20, 0, 0, 255}, {20, 0, 0, 255}}};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  unsigned char image[2][2][4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  EXPECT_EQ(image[0][0][0], 20);
  EXPECT_EQ(image[1][0][0], 10);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_PACK_INVERT_MESA, 0);
  glPopClientAttrib();
  glGetIntegerv(GL_PACK_INVERT_MESA, &invert);
  EXPECT_EQ(invert, 5);
  glPixelStorei(GL_PACK_INVERT_MESA, 0);
  glReadPixels(0, 0, 1, 3, GL_RGBA, GL_UNSIGNED_BYTE, rows);
  EXPECT_EQ(rows[0][0], 255);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClearReadTest, OSMesaYUpZeroFlipsTheClientBuffer) {
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  GLint yup = -1;
  OSMesaGetIntegerv(OSMESA_Y_UP, &yup);
  EXPECT_EQ(yup, 0);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor4f(1, 1, 1, 1);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 0);
  glVertex2f(-1, 0);
  glEnd();
  glFinish();
  unsigned char low[4] = {0, 0, 0, 0};
  glReadPixels(3, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, low);
  EXPECT_EQ(low[0], 255) << "glReadPixels still counts rows from the bottom";
  for (int y = 0; y < kHeight; ++y) {
    const unsigned char* row = pixels() + y * kWidth * 4;
    EXPECT_EQ(row[4 * 20], y < kHeight / 2 ? 0 : 255) << "client buffer row " << y;
  }
  OSMesaPixelStore(OSMESA_Y_UP, 1);
}

// §4.3.2: pixels outside the window have undefined values, but those inside
// read correctly and nothing is written outside the destination image.
TEST_F(ClearReadTest, ReadPixelsStraddlingTheWindow) {
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  const int x0 = -5, y0 = kHeight - 3, w = 10, h = 6;  // overlaps the top left corner
  std::vector<unsigned char> out(w * h * 4 + 64, 0x3C);
  glReadPixels(x0, y0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_NO_GL_ERROR();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x0 + x < 0 || y0 + y >= kHeight) continue;
      const unsigned char* p = out.data() + 4 * (y * w + x);
      EXPECT_TRUE(p[0] == 51 && p[1] == 102 && p[2] == 153 && p[3] == 204) << "pixel " << x << "," << y;
    }
  for (size_t b = w * h * 4; b < out.size(); ++b) ASSERT_EQ(out[b], 0x3C) << "wrote past the image";
  // Entirely outside: no error, nothing read from outside the framebuffer.
  glReadPixels(-100, -100, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  glReadPixels(kWidth, kHeight, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_NO_GL_ERROR();
}

// §4.2.3: clearing a buffer the framebuffer does not have (stencil,
// accumulation) has no effect and is no error.
TEST_F(ClearReadTest, ClearOfAbsentBuffersIsNoError) {
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glClearColor(0, 0, 0, 0);
  glClear(GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(pixels()[0], 255);
}

// Binding a context to a buffer of another size resizes its framebuffer (the
// depth buffer too), and leaves the viewport alone.
TEST_F(ClearReadTest, MakeCurrentWithAnotherSizeResizes) {
  const int w = 24, h = 10, guard = 256;
  std::vector<unsigned char> small(w * h * 4 + guard, 0x3C);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, small.data(), GL_UNSIGNED_BYTE, w, h), GL_TRUE);
  GLint v = 0;
  OSMesaGetIntegerv(OSMESA_WIDTH, &v);
  EXPECT_EQ(v, w);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &v);
  EXPECT_EQ(v, h);
  // Mesa 22 corrupts its heap (a crash or "free(): invalid pointer" later)
  // when a context whose depth buffer OSMesaGetDepthBuffer handed out is bound
  // to a buffer of another size and then clears.
  if (!kTestingAgainstMesa) {
    GLint dw = 0, dh = 0, bytes = 0;
    void* depth = nullptr;
    ASSERT_EQ(OSMesaGetDepthBuffer(ctx_, &dw, &dh, &bytes, &depth), GL_TRUE);
    EXPECT_EQ(dw, w);
    EXPECT_EQ(dh, h);
  }
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glFinish();
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < w * h; ++i) {
    const unsigned char* p = small.data() + 4 * i;
    ASSERT_TRUE(p[0] == 51 && p[1] == 102 && p[2] == 153 && p[3] == 204) << "pixel " << i;
  }
  for (int b = w * h * 4; b < w * h * 4 + guard; ++b) ASSERT_EQ(small[b], 0x3C) << "wrote past the buffer";
  GLfloat z = -1;
  glReadPixels(w - 1, h - 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &z);
  EXPECT_NEAR(z, 0.5, 1e-6);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  OSMesaGetIntegerv(OSMESA_WIDTH, &v);
  EXPECT_EQ(v, kWidth);
  glClear(GL_COLOR_BUFFER_BIT);
  const unsigned char* p = pixels() + 4 * (kWidth * kHeight - 1);
  EXPECT_TRUE(p[0] == 51 && p[1] == 102 && p[2] == 153 && p[3] == 204) << "the last pixel of the big buffer";
}

// OSMESA_ROW_LENGTH: rows of the client buffer are that many pixels apart.
TEST_F(ClearReadTest, OSMesaRowLength) {
  const int w = 20, h = 6, rowLength = 32;
  std::vector<unsigned char> mem(rowLength * h * 4, 0x3C);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, mem.data(), GL_UNSIGNED_BYTE, w, h), GL_TRUE);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, rowLength);
  GLint v = 0;
  OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v);
  EXPECT_EQ(v, rowLength);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < rowLength; ++x) {
      const unsigned char* p = mem.data() + 4 * (y * rowLength + x);
      if (x < w) {
        ASSERT_EQ(p[0], 255) << "pixel " << x << "," << y;
      } else {
        ASSERT_EQ(p[0], 0x3C) << "the row padding at " << x << "," << y << " was written";
      }
    }
  OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
}

// ---- the OSMesa entry points -------------------------------------------------------

TEST_F(ClearReadTest, OSMesaGetColorBuffer) {
  GLint w = 0, h = 0, format = 0;
  void* buf = nullptr;
  ASSERT_EQ(OSMesaGetColorBuffer(ctx_, &w, &h, &format, &buf), GL_TRUE);
  EXPECT_EQ(w, kWidth);
  EXPECT_EQ(h, kHeight);
  EXPECT_EQ(format, OSMESA_RGBA);
  EXPECT_EQ(buf, buffer_) << "the client's own memory";
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  const unsigned char* p = static_cast<const unsigned char*>(buf);
  EXPECT_EQ(p[0], 51);
  EXPECT_EQ(p[1], 102);
  EXPECT_EQ(p[2], 153);
  EXPECT_EQ(p[3], 204);
}

TEST_F(ClearReadTest, OSMesaGetDepthBuffer) {
  GLint w = 0, h = 0, bytes = 0;
  void* buf = nullptr;
  ASSERT_EQ(OSMesaGetDepthBuffer(ctx_, &w, &h, &bytes, &buf), GL_TRUE);
  EXPECT_EQ(w, kWidth);
  EXPECT_EQ(h, kHeight);
  EXPECT_EQ(bytes, 4) << "a 24-bit depth buffer has 4 bytes a value";
  ASSERT_NE(buf, nullptr);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glFinish();
  ASSERT_EQ(OSMesaGetDepthBuffer(ctx_, &w, &h, &bytes, &buf), GL_TRUE);
  const GLuint* z = static_cast<const GLuint*>(buf);
  EXPECT_EQ(z[0] & 0xFFFFFFu, 0xFFFFFFu);
  EXPECT_EQ(z[w * h - 1] & 0xFFFFFFu, 0xFFFFFFu);
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  glFinish();
  ASSERT_EQ(OSMesaGetDepthBuffer(ctx_, &w, &h, &bytes, &buf), GL_TRUE);
  z = static_cast<const GLuint*>(buf);
  EXPECT_NEAR(static_cast<double>(z[7] & 0xFFFFFFu), 0x800000, 1.0);
}

TEST(OSMesaTest, GetDepthBufferWithoutDepthFails) {
  ScopedContext c(OSMESA_RGBA, 0, 16, 16, 4);
  ASSERT_TRUE(c.makeCurrent());
  EXPECT_EQ(GetInt(GL_DEPTH_BITS), 0);
  GLint w = -1, h = -1, bytes = -1;
  void* buf = reinterpret_cast<void*>(1);
  EXPECT_EQ(OSMesaGetDepthBuffer(c.get(), &w, &h, &bytes, &buf), GL_FALSE);
  // §4.3.2: reading depth with no depth buffer is GL_INVALID_OPERATION.
  GLfloat d[4] = {-1, -1, -1, -1};
  glReadPixels(0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, d);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  for (GLfloat v : d) EXPECT_EQ(v, -1.0f);
}

TEST(OSMesaTest, DepthBitsFollowTheRequest) {
  const struct { GLint asked, bits, bytes; } cases[] = {{16, 16, 2}, {24, 24, 4}, {32, 24, 4}};
  for (const auto& k : cases) {
    SCOPED_TRACE(::testing::Message() << "depthBits " << k.asked);
    ScopedContext c(OSMESA_RGBA, k.asked, 8, 8, 4);
    ASSERT_TRUE(c.makeCurrent());
    EXPECT_EQ(GetInt(GL_DEPTH_BITS), k.bits);
    GLint w = 0, h = 0, bytes = 0;
    void* buf = nullptr;
    EXPECT_EQ(OSMesaGetDepthBuffer(c.get(), &w, &h, &bytes, &buf), GL_TRUE);
    EXPECT_EQ(bytes, k.bytes);
    EXPECT_EQ(w, 8);
    EXPECT_EQ(h, 8);
  }
}

TEST_F(ClearReadTest, OSMesaGetIntegerv) {
  GLint v = -1;
  OSMesaGetIntegerv(OSMESA_WIDTH, &v);
  EXPECT_EQ(v, kWidth);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &v);
  EXPECT_EQ(v, kHeight);
  OSMesaGetIntegerv(OSMESA_FORMAT, &v);
  EXPECT_EQ(v, OSMESA_RGBA);
  OSMesaGetIntegerv(OSMESA_TYPE, &v);
  EXPECT_EQ(v, GL_UNSIGNED_BYTE);
  OSMesaGetIntegerv(OSMESA_Y_UP, &v);
  EXPECT_EQ(v, 1);
  GLint maxW = -1, maxH = -1;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxW);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &maxH);
  EXPECT_GE(maxW, 4096);
  EXPECT_GE(maxH, 4096);
}

TEST_F(ClearReadTest, OSMesaGetCurrentContext) {
  EXPECT_EQ(OSMesaGetCurrentContext(), ctx_);
  ASSERT_EQ(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0), GL_TRUE);
  EXPECT_EQ(OSMesaGetCurrentContext(), nullptr);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(OSMesaGetCurrentContext(), ctx_);
}

TEST_F(ClearReadTest, OSMesaGetProcAddress) {
  typedef void (*BeginFn)(GLenum);
  typedef void (*ClearColorFn)(GLfloat, GLfloat, GLfloat, GLfloat);
  OSMESAproc begin = OSMesaGetProcAddress("glBegin");
  ASSERT_NE(begin, nullptr);
  OSMESAproc end = OSMesaGetProcAddress("glEnd");
  ASSERT_NE(end, nullptr);
  OSMESAproc clearColor = OSMesaGetProcAddress("glClearColor");
  ASSERT_NE(clearColor, nullptr);
  EXPECT_NE(OSMesaGetProcAddress("glGetIntegerv"), nullptr);
  EXPECT_NE(OSMesaGetProcAddress("glProvokingVertex"), nullptr);
  EXPECT_NE(OSMesaGetProcAddress("OSMesaGetCurrentContext"), nullptr);
  EXPECT_EQ(OSMesaGetProcAddress("notAGLFunction"), nullptr);
  EXPECT_EQ(OSMesaGetProcAddress(""), nullptr);
  // Mesa's glapi hands out a dispatch stub for any name that starts with
  // "gl", so it answers these too.
  if (!kTestingAgainstMesa) {
    EXPECT_EQ(OSMesaGetProcAddress("glBogusFunctionThatDoesNotExist"), nullptr);
    EXPECT_EQ(OSMesaGetProcAddress("glBegin2"), nullptr);
  }
  // The pointers are the commands.
  reinterpret_cast<ClearColorFn>(clearColor)(0.5f, 0.25f, 0.125f, 1.0f);
  EXPECT_EQ(GetFloat(GL_COLOR_CLEAR_VALUE), 0.5f);
  reinterpret_cast<BeginFn>(begin)(GL_POINTS);
  glMatrixMode(GL_PROJECTION);  // inside: refused
  reinterpret_cast<void (*)()>(end)();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_NO_GL_ERROR();
}

TEST(OSMesaTest, MakeCurrentRefusesBadArguments) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  ASSERT_NE(ctx, nullptr);
  std::vector<unsigned char> buf(64 * 64 * 4);
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_INT, 64, 64), GL_FALSE) << "type GL_INT";
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_BYTE, 64, 64), GL_FALSE) << "type GL_BYTE";
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), 0xFFFF, 64, 64), GL_FALSE) << "type 0xFFFF";
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 0, 64), GL_FALSE) << "width 0";
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 64, 0), GL_FALSE) << "height 0";
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, -5, 64), GL_FALSE) << "width -5";
  EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 64, -5), GL_FALSE) << "height -5";
  GLint maxW = 0;
  ASSERT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, 64, 64), GL_TRUE);
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &maxW);
  ASSERT_GT(maxW, 0);
  // Mesa's gallium OSMesa does not check the size against OSMESA_MAX_WIDTH.
  if (!kTestingAgainstMesa) {
    EXPECT_EQ(OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, maxW + 1, 1), GL_FALSE) << "width > max";
  }
  EXPECT_EQ(OSMesaMakeCurrent(ctx, NULL, GL_UNSIGNED_BYTE, 64, 64), GL_FALSE) << "no buffer";
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

TEST(OSMesaTest, CreateContextRefusesABadFormat) {
  EXPECT_EQ(OSMesaCreateContextExt(0xFFFF, 24, 0, 0, NULL), nullptr);
}

// A known colour lands at the right bytes of each format's client buffer. An
// odd size checks that rows are width * bytesPerPixel apart.
TEST(OSMesaTest, EveryFormatClearsToTheRightBytes) {
  const struct {
    const char* name;
    GLenum format;
    int bpp;
    int r, g, b, a;  // byte offsets, a = -1: not stored
  } formats[] = {
      {"OSMESA_RGBA", OSMESA_RGBA, 4, 0, 1, 2, 3}, {"OSMESA_BGRA", OSMESA_BGRA, 4, 2, 1, 0, 3},
      {"OSMESA_ARGB", OSMESA_ARGB, 4, 1, 2, 3, 0}, {"OSMESA_RGB", OSMESA_RGB, 3, 0, 1, 2, -1},
      {"OSMESA_BGR", OSMESA_BGR, 3, 2, 1, 0, -1},
  };
  const int w = 17, h = 9;
  for (const auto& f : formats) {
    SCOPED_TRACE(f.name);
    // Mesa's gallium OSMesa has no OSMESA_BGR / GL_UNSIGNED_BYTE format
    // (osmesa.c: "No gallium format for this one"); MakeCurrent fails.
    if (kTestingAgainstMesa && f.format == OSMESA_BGR) continue;
    ScopedContext c(f.format, 24, w, h, f.bpp);
    ASSERT_NE(c.get(), nullptr);
    ASSERT_TRUE(c.makeCurrent());
    GLint fmt = -1;
    OSMesaGetIntegerv(OSMESA_FORMAT, &fmt);
    EXPECT_EQ(fmt, static_cast<GLint>(f.format));
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    EXPECT_NO_GL_ERROR();
    for (int i = 0; i < w * h; ++i) {
      const unsigned char* p = c.bytes() + f.bpp * i;
      ASSERT_TRUE(p[f.r] == 51 && p[f.g] == 102 && p[f.b] == 153 && (f.a < 0 || p[f.a] == 204))
          << "pixel " << i << ": bytes " << int(p[0]) << " " << int(p[1]) << " " << int(p[2]) << " "
          << (f.bpp == 4 ? int(p[3]) : -1);
    }
    unsigned char rgba[4] = {0, 0, 0, 0};
    glReadPixels(w - 1, h - 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    EXPECT_EQ(rgba[0], 51);
    EXPECT_EQ(rgba[1], 102);
    EXPECT_EQ(rgba[2], 153);
    if (f.a >= 0) {
      EXPECT_EQ(rgba[3], 204);
    }
    GLint w2 = 0, h2 = 0, fmt2 = 0;
    void* buf = nullptr;
    ASSERT_EQ(OSMesaGetColorBuffer(c.get(), &w2, &h2, &fmt2, &buf), GL_TRUE);
    EXPECT_EQ(w2, w);
    EXPECT_EQ(h2, h);
    EXPECT_EQ(fmt2, static_cast<GLint>(f.format));
    EXPECT_EQ(buf, static_cast<void*>(c.bytes()));
  }
}

}  // namespace
}  // namespace glfx_test
