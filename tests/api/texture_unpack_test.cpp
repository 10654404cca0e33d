// Pixel unpack for texture images (GL 2.1 §3.6): formats, types, the packed
// types, glPixelStore state, pixel unpack buffers, pixel transfer; and the
// pack side of glGetTexImage.
#include "api/gl_test_fixture.h"

using namespace glfx_test;

namespace {

class TextureUnpackTest : public GLTest {};

std::vector<GLubyte> ReadRGBA8(int texels) {
  std::vector<GLubyte> back(texels * 4, 0xEE);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  return back;
}

TEST_F(TextureUnpackTest, FormatsBecomeRGBA) {
  const GLubyte px[4] = {10, 20, 30, 40};
  struct Case {
    GLenum format;
    GLubyte r, g, b, a;
  } cases[] = {
      {GL_RED, 10, 0, 0, 255},         {GL_GREEN, 0, 10, 0, 255},
      {GL_BLUE, 0, 0, 10, 255},        {GL_ALPHA, 0, 0, 0, 10},
      {GL_RGB, 10, 20, 30, 255},       {GL_BGR, 30, 20, 10, 255},
      {GL_RGBA, 10, 20, 30, 40},       {GL_BGRA, 30, 20, 10, 40},
      {GL_LUMINANCE, 10, 10, 10, 255}, {GL_LUMINANCE_ALPHA, 10, 10, 10, 20},
  };
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, c.format, GL_UNSIGNED_BYTE, px);
    ASSERT_NO_GL_ERROR();
    std::vector<GLubyte> back = ReadRGBA8(1);
    EXPECT_EQ(back[0], c.r) << std::hex << c.format;
    EXPECT_EQ(back[1], c.g) << std::hex << c.format;
    EXPECT_EQ(back[2], c.b) << std::hex << c.format;
    EXPECT_EQ(back[3], c.a) << std::hex << c.format;
  }
  // A luminance texture takes R of RGBA data; glGetTexImage gives it back as R.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  std::vector<GLubyte> back = ReadRGBA8(1);
  EXPECT_EQ(back[0], 10);
  EXPECT_EQ(back[1], 0);
  EXPECT_EQ(back[2], 0);
  EXPECT_EQ(back[3], 255);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_INTENSITY8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  back = ReadRGBA8(1);
  EXPECT_EQ(back[0], 10);
  EXPECT_EQ(back[3], 255);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  back = ReadRGBA8(1);
  EXPECT_EQ(back[0], 0);
  EXPECT_EQ(back[3], 40);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8_ALPHA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  back = ReadRGBA8(1);
  EXPECT_EQ(back[0], 10);
  EXPECT_EQ(back[3], 40);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureUnpackTest, PackedTypes) {
  // One texel of each packed type, R = max, G = 0, B = a middle value, A = max/low.
  const GLubyte b332 = (7 << 5) | (0 << 2) | 1;      // R 7, G 0, B 1
  const GLubyte b233 = 7 | (0 << 3) | (1 << 6);      // R 7, G 0, B 1
  const GLushort s565 = (31 << 11) | (0 << 5) | 16;  // R 31, G 0, B 16
  const GLushort s565r = 31 | (0 << 5) | (16 << 11);
  const GLushort s4444 = (15 << 12) | (0 << 8) | (5 << 4) | 10;
  const GLushort s4444r = 15 | (0 << 4) | (5 << 8) | (10 << 12);
  const GLushort s5551 = (31 << 11) | (0 << 6) | (10 << 1) | 1;
  const GLushort s1555r = 31 | (0 << 5) | (10 << 10) | (1u << 15);
  const GLuint i8888 = (255u << 24) | (0 << 16) | (51 << 8) | 102;
  const GLuint i8888r = 255u | (0 << 8) | (51 << 16) | (102u << 24);
  const GLuint i1010102 = (1023u << 22) | (0 << 12) | (341 << 2) | 2;
  const GLuint i2101010r = 1023u | (0 << 10) | (341 << 20) | (2u << 30);
  struct Case {
    GLenum format, type;
    const void* data;
    int r, g, b, a;
  } cases[] = {
      {GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &b332, 255, 0, 85, 255},
      {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, &b233, 255, 0, 85, 255},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &s565, 255, 0, 132, 255},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, &s565r, 255, 0, 132, 255},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &s4444, 255, 0, 85, 170},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, &s4444r, 255, 0, 85, 170},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, &s4444, 85, 0, 255, 170},
      {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, &s5551, 255, 0, 82, 255},
      {GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV, &s1555r, 255, 0, 82, 255},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &i8888, 255, 0, 51, 102},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, &i8888r, 255, 0, 51, 102},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, &i8888r, 51, 0, 255, 102},
      {GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, &i1010102, 255, 0, 85, 170},
      {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, &i2101010r, 255, 0, 85, 170},
  };
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, c.format, c.type, c.data);
    ASSERT_NO_GL_ERROR() << std::hex << c.type;
    std::vector<GLubyte> back = ReadRGBA8(1);
    EXPECT_EQ(back[0], c.r) << std::hex << c.format << " " << c.type;
    EXPECT_EQ(back[1], c.g) << std::hex << c.format << " " << c.type;
    EXPECT_EQ(back[2], c.b) << std::hex << c.format << " " << c.type;
    EXPECT_EQ(back[3], c.a) << std::hex << c.format << " " << c.type;
  }
}

TEST_F(TextureUnpackTest, ElementTypes) {
  const GLushort us[4] = {0, 65535, 32768, 257 * 40};
  const GLshort s[4] = {-5, 32767, 16384, 0};
  const GLuint ui[4] = {0, 0xffffffffu, 0x80000000u, 0x28282828u};
  const GLint i[4] = {-7, 0x7fffffff, 0x40000000, 0};
  const GLfloat f[4] = {-0.5f, 1.5f, 0.5f, 40 / 255.0f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT, us);
  std::vector<GLubyte> b = ReadRGBA8(1);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 128);
  EXPECT_EQ(b[3], 40);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_SHORT, s);
  b = ReadRGBA8(1);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 128);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_INT, ui);
  b = ReadRGBA8(1);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 128);
  EXPECT_EQ(b[3], 40);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_INT, i);
  b = ReadRGBA8(1);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 128);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_FLOAT, f);
  b = ReadRGBA8(1);
  EXPECT_EQ(b[0], 0);  // clamped
  EXPECT_EQ(b[1], 255);
  EXPECT_EQ(b[2], 128);
  EXPECT_EQ(b[3], 40);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureUnpackTest, PixelStoreLayout) {
  // A 3x2 RGB image inside a 5-pixel-wide, aligned-to-8 client array, two
  // rows and one pixel skipped.
  std::vector<GLubyte> client(16 * 4, 0);
  const int stride = 16;  // 5 * 3 = 15 bytes, aligned to 8
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 3; ++c)
        client[(y + 2) * stride + (x + 1) * 3 + c] = static_cast<GLubyte>(10 * (y * 3 + x) + c + 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  EXPECT_EQ(GetInt(GL_UNPACK_ROW_LENGTH), 5);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, client.data());
  ASSERT_NO_GL_ERROR();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  std::vector<GLubyte> back = ReadRGBA8(6);
  for (int t = 0; t < 6; ++t) {
    EXPECT_EQ(back[t * 4], 10 * t + 1) << t;
    EXPECT_EQ(back[t * 4 + 2], 10 * t + 3) << t;
    EXPECT_EQ(back[t * 4 + 3], 255) << t;
  }
}

TEST_F(TextureUnpackTest, SwapBytesAndImageHeight) {
  const GLushort px[2] = {0x00ff, 0xff00};  // swapped: 0xff00, 0x00ff
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  EXPECT_EQ(GetInt(GL_UNPACK_SWAP_BYTES), 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE16, 2, 1, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT, px);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  GLushort back[2 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, back);
  EXPECT_EQ(back[0], 0xff00);
  EXPECT_EQ(back[4], 0x00ff);

  // 3D: two 1x1 slices taken from images of height 2, one image skipped.
  GLubyte slices[4 * 4] = {};
  for (int i = 0; i < 4; ++i) slices[i * 4] = static_cast<GLubyte>(50 * i + 10);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 2);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  EXPECT_EQ(GetInt(GL_UNPACK_IMAGE_HEIGHT), 2);
  EXPECT_EQ(GetInt(GL_UNPACK_SKIP_IMAGES), 1);
  // Images are 2 rows of 4 bytes: image 1 starts at byte 8 -> texel 2.
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, slices);
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  GLubyte out[4];
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 110);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureUnpackTest, PixelTransferScaleAndBias) {
  const GLubyte px[4] = {100, 100, 100, 100};
  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.5f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glPixelTransferf(GL_BLUE_BIAS, 0.0f);
  std::vector<GLubyte> back = ReadRGBA8(1);
  EXPECT_EQ(back[0], 200);
  EXPECT_EQ(back[1], 100);
  EXPECT_EQ(back[2], 228);  // 100/255 + 0.5 = 0.892 -> 227.5 -> 228
  EXPECT_EQ(back[3], 100);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureUnpackTest, PixelUnpackBuffer) {
  GLuint buffer;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
  const GLubyte data[12] = {0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8};
  glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof data, data, GL_STATIC_DRAW);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(4));
  ASSERT_NO_GL_ERROR();
  // One byte past the end: refused, the level unchanged.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(5));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(9));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  std::vector<GLubyte> back = ReadRGBA8(2);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(back[i], i + 1);
  glDeleteBuffers(1, &buffer);
}

TEST_F(TextureUnpackTest, SubImages) {
  std::vector<GLubyte> zero(4 * 4 * 4, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero.data());
  const GLubyte two[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_NO_GL_ERROR();
  std::vector<GLubyte> back = ReadRGBA8(16);
  EXPECT_EQ(back[(3 * 4 + 2) * 4], 1);
  EXPECT_EQ(back[(3 * 4 + 3) * 4 + 3], 8);
  EXPECT_EQ(back[(3 * 4 + 1) * 4], 0);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);  // the level is not defined
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_NO_GL_ERROR();
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, two);
  EXPECT_NO_GL_ERROR();
  glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexSubImage1D(GL_TEXTURE_2D, 0, 0, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  // 1D and 3D.
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero.data());
  glTexSubImage1D(GL_TEXTURE_1D, 0, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, two);
  GLubyte row[16];
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, row);
  EXPECT_EQ(row[4], 1);
  EXPECT_EQ(row[11], 8);
  EXPECT_EQ(row[15], 0);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero.data());
  glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, two);
  GLubyte cube[32];
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, cube);
  EXPECT_EQ(cube[28], 1);
  EXPECT_EQ(cube[24], 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureUnpackTest, GetTexImageErrorsAndTypes) {
  const GLubyte px[8] = {0, 51, 102, 255, 255, 204, 153, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  GLubyte out[64];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_FLOAT, out);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetTexImage(GL_TEXTURE_2D, 3, GL_RGBA, GL_FLOAT, out);
  EXPECT_NO_GL_ERROR();  // an undefined level: nothing written
  glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_FLOAT, out);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);

  GLubyte bgr[6];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGR, GL_UNSIGNED_BYTE, bgr);
  EXPECT_EQ(bgr[0], 102);
  EXPECT_EQ(bgr[2], 0);
  EXPECT_EQ(bgr[3], 153);
  GLushort s565[2];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, s565);
  EXPECT_EQ(s565[0], (0 << 11) | (13 << 5) | 12);  // 51 -> 12.6 of 63, 102 -> 12.4 of 31
  GLuint i8888[2];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, i8888);
  EXPECT_EQ(i8888[1], (0u << 24) | (255u << 16) | (204u << 8) | 153u);
  GLfloat f[2];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_GREEN, GL_FLOAT, f);
  EXPECT_FLOAT_EQ(f[0], 0.2f);
  EXPECT_FLOAT_EQ(f[1], 0.8f);
  GLubyte la[4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  EXPECT_EQ(la[0], 0);  // L = R
  EXPECT_EQ(la[1], 255);
  EXPECT_EQ(la[2], 255);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  EXPECT_NO_GL_ERROR();

  // Into a pack buffer, and not past its end.
  GLuint buffer;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  glBufferData(GL_PIXEL_PACK_BUFFER, 12, nullptr, GL_STREAM_READ);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(4));
  EXPECT_NO_GL_ERROR();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, reinterpret_cast<void*>(5));
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLubyte stored[12] = {};
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, 12, stored);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(stored[4 + i], px[i]);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
}

TEST_F(TextureUnpackTest, DepthTextures) {
  const GLushort d16[2] = {0x1234, 0xffff};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 2, 1, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, d16);
  ASSERT_NO_GL_ERROR();
  GLushort back[2];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, back);
  EXPECT_EQ(back[0], 0x1234);
  EXPECT_EQ(back[1], 0xffff);
  GLubyte rgba[8];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  const GLfloat df[2] = {0.25f, 0.75f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, df);
  GLfloat fb[2];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fb);
  EXPECT_NEAR(fb[0], 0.25f, 1e-6);
  EXPECT_NEAR(fb[1], 0.75f, 1e-6);
  EXPECT_NO_GL_ERROR();
}

// GL 2.1 §3.8.1: one- and two-dimensional images ignore the skip-images
// state, packing and unpacking; a 1D image still skips rows (as Mesa does).
TEST_F(TextureUnpackTest, SkipImagesOnlyForThreeDimensions) {
  GLubyte img[64];
  for (int i = 0; i < 64; ++i) img[i] = static_cast<GLubyte>(i + 1);
  GLubyte out[8] = {};
  auto first = [&] { return std::array<int, 5>{out[0], out[1], out[2], out[3], out[4]}; };
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(first(), (std::array<int, 5>{1, 2, 3, 4, 0}));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img + 8);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(first(), (std::array<int, 5>{1, 2, 3, 4, 0}));
  glPixelStorei(GL_PACK_SKIP_IMAGES, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(first(), (std::array<int, 5>{9, 10, 11, 12, 0}));
  glPixelStorei(GL_PACK_SKIP_IMAGES, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(first(), (std::array<int, 5>{5, 6, 7, 8, 0}));
  // A list replays the image it captured the same way.
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, img + 16);
  glEndList();
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  glCallList(list);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(first(), (std::array<int, 5>{17, 18, 19, 20, 0}));
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
