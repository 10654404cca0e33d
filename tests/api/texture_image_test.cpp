// Texture images (GL 2.1 §3.8.1-3.8.3, §3.8.11, §6.1.4): every internal
// format stored at llvmpipe's precision, the errors Mesa gives, borders,
// proxies, memory limits, sub-images, glGetTexImage, display lists.

#include "api/gl_test_fixture.h"

using namespace glfx_test;

namespace {

class TextureImageTest : public GLTest {};

GLint LevelInt(GLenum target, GLint level, GLenum pname) {
  GLint v = -12345;
  glGetTexLevelParameteriv(target, level, pname, &v);
  return v;
}

struct Sizes {
  GLint internal;
  int r, g, b, a, l, i, d;
};

// Mesa 22.3.6 llvmpipe (probed with GL_RGBA/GL_UNSIGNED_BYTE data, depth
// with GL_DEPTH_COMPONENT/GL_UNSIGNED_BYTE).
const Sizes kSizes[] = {
    {1, 0, 0, 0, 0, 8, 0, 0},
    {2, 0, 0, 0, 8, 8, 0, 0},
    {3, 8, 8, 8, 0, 0, 0, 0},
    {4, 8, 8, 8, 8, 0, 0, 0},
    {GL_ALPHA, 0, 0, 0, 8, 0, 0, 0},
    {GL_ALPHA4, 0, 0, 0, 8, 0, 0, 0},
    {GL_ALPHA8, 0, 0, 0, 8, 0, 0, 0},
    {GL_ALPHA12, 0, 0, 0, 16, 0, 0, 0},
    {GL_ALPHA16, 0, 0, 0, 16, 0, 0, 0},
    {GL_LUMINANCE, 0, 0, 0, 0, 8, 0, 0},
    {GL_LUMINANCE4, 0, 0, 0, 0, 8, 0, 0},
    {GL_LUMINANCE8, 0, 0, 0, 0, 8, 0, 0},
    {GL_LUMINANCE12, 0, 0, 0, 0, 16, 0, 0},
    {GL_LUMINANCE16, 0, 0, 0, 0, 16, 0, 0},
    {GL_LUMINANCE_ALPHA, 0, 0, 0, 8, 8, 0, 0},
    {GL_LUMINANCE4_ALPHA4, 0, 0, 0, 4, 4, 0, 0},
    {GL_LUMINANCE6_ALPHA2, 0, 0, 0, 8, 8, 0, 0},
    {GL_LUMINANCE8_ALPHA8, 0, 0, 0, 8, 8, 0, 0},
    {GL_LUMINANCE12_ALPHA4, 0, 0, 0, 16, 16, 0, 0},
    {GL_LUMINANCE12_ALPHA12, 0, 0, 0, 16, 16, 0, 0},
    {GL_LUMINANCE16_ALPHA16, 0, 0, 0, 16, 16, 0, 0},
    {GL_INTENSITY, 0, 0, 0, 0, 0, 8, 0},
    {GL_INTENSITY4, 0, 0, 0, 0, 0, 8, 0},
    {GL_INTENSITY8, 0, 0, 0, 0, 0, 8, 0},
    {GL_INTENSITY12, 0, 0, 0, 0, 0, 16, 0},
    {GL_INTENSITY16, 0, 0, 0, 0, 0, 16, 0},
    {GL_RGB, 8, 8, 8, 0, 0, 0, 0},
    {GL_R3_G3_B2, 3, 3, 2, 0, 0, 0, 0},
    {GL_RGB4, 4, 4, 4, 0, 0, 0, 0},
    {GL_RGB5, 5, 5, 5, 0, 0, 0, 0},
    {GL_RGB8, 8, 8, 8, 0, 0, 0, 0},
    {GL_RGB10, 10, 10, 10, 0, 0, 0, 0},
    {GL_RGB12, 16, 16, 16, 0, 0, 0, 0},
    {GL_RGB16, 16, 16, 16, 0, 0, 0, 0},
    {GL_RGBA, 8, 8, 8, 8, 0, 0, 0},
    {GL_RGBA2, 4, 4, 4, 4, 0, 0, 0},
    {GL_RGBA4, 4, 4, 4, 4, 0, 0, 0},
    {GL_RGB5_A1, 5, 5, 5, 1, 0, 0, 0},
    {GL_RGBA8, 8, 8, 8, 8, 0, 0, 0},
    {GL_RGB10_A2, 10, 10, 10, 2, 0, 0, 0},
    {GL_RGBA12, 16, 16, 16, 16, 0, 0, 0},
    {GL_RGBA16, 16, 16, 16, 16, 0, 0, 0},
    {GL_SRGB8_ALPHA8, 8, 8, 8, 8, 0, 0, 0},
    {GL_SLUMINANCE8, 0, 0, 0, 0, 8, 0, 0},
    {GL_COMPRESSED_ALPHA, 0, 0, 0, 8, 0, 0, 0},
    {GL_COMPRESSED_INTENSITY, 0, 0, 0, 0, 0, 8, 0},
    {GL_DEPTH_COMPONENT, 0, 0, 0, 0, 0, 0, 24},
    {GL_DEPTH_COMPONENT16, 0, 0, 0, 0, 0, 0, 16},
    {GL_DEPTH_COMPONENT24, 0, 0, 0, 0, 0, 0, 24},
    {GL_DEPTH_COMPONENT32, 0, 0, 0, 0, 0, 0, 32},
};

TEST_F(TextureImageTest, EveryInternalFormatAtLlvmpipesPrecision) {
  static GLubyte pixels[4 * 4 * 4];
  for (const Sizes& s : kSizes) {
    const bool depth = s.d != 0;
    glTexImage2D(GL_TEXTURE_2D, 0, s.internal, 4, 4, 0, depth ? GL_DEPTH_COMPONENT : GL_RGBA,
                 GL_UNSIGNED_BYTE, pixels);
    ASSERT_NO_GL_ERROR() << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE), s.r) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE), s.g) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE), s.b) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE), s.a) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE), s.l) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_INTENSITY_SIZE), s.i) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE), s.d) << std::hex << s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, 0x88F1 /* GL_TEXTURE_STENCIL_SIZE */), 0) << std::hex << s.internal;
    ASSERT_NO_GL_ERROR() << std::hex << s.internal;
    // A generic compressed format Mesa cannot compress reads as its base format.
    const GLint reported = s.internal == GL_COMPRESSED_ALPHA       ? GL_ALPHA
                           : s.internal == GL_COMPRESSED_INTENSITY ? GL_INTENSITY
                                                                   : s.internal;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT), reported);
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 4);
  }
}

// The unsized GL_RGB, GL_RGBA and GL_DEPTH_COMPONENT take their precision
// from the client data's type.
TEST_F(TextureImageTest, UnsizedFormatsFollowTheType) {
  static GLubyte pixels[4 * 4 * 16];
  struct Case {
    GLint internal;
    GLenum format, type;
    int red, alpha, depth;
  } cases[] = {
      {GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT, 16, 16, 0},
      {GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 4, 4, 0},
      {GL_RGBA, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 5, 1, 0},
      {GL_RGBA, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 10, 2, 0},
      {GL_RGBA, GL_RGBA, GL_FLOAT, 8, 8, 0},
      {GL_RGBA, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 8, 8, 0},
      {GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 5, 0, 0},
      {GL_RGB, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 3, 0, 0},
      {GL_RGB, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 10, 0, 0},
      {GL_RGB, GL_RGB, GL_UNSIGNED_SHORT, 8, 0, 0},
      {4, GL_RGBA, GL_UNSIGNED_SHORT, 8, 8, 0},
      {GL_RGBA8, GL_RGBA, GL_UNSIGNED_SHORT, 8, 8, 0},
      {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 0, 0, 16},
      {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 0, 0, 32},
      {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_FLOAT, 0, 0, 24},
  };
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, c.internal, 4, 4, 0, c.format, c.type, pixels);
    ASSERT_NO_GL_ERROR();
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE), c.red)
        << std::hex << c.internal << " " << c.type;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE), c.alpha)
        << std::hex << c.internal << " " << c.type;
    EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE), c.depth)
        << std::hex << c.internal << " " << c.type;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, pixels);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE), 6);
}

// A ramp of 8-bit values stored at n bits and read back as floats: the
// stored value is round(v * (2^n - 1) / 255), except that more than 8 bits
// repeat the byte's bits ((v << 2) | (v >> 6) for 10).
TEST_F(TextureImageTest, BytesConvertAsMesaConvertsThem) {
  std::vector<GLubyte> ramp(256 * 4);
  for (int i = 0; i < 256 * 4; ++i) ramp[i] = static_cast<GLubyte>(i / 4);
  struct Case {
    GLint internal;
    int bits;
  } cases[] = {{GL_RGBA4, 4}, {GL_RGB5, 5},      {GL_R3_G3_B2, 3},
               {GL_RGBA8, 8}, {GL_RGB10_A2, 10}, {GL_RGBA16, 16}};
  std::vector<GLfloat> back(256 * 4);
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, c.internal, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp.data());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, back.data());
    ASSERT_NO_GL_ERROR();
    const int max = (1 << c.bits) - 1;
    for (int v = 0; v < 256; ++v) {
      int expected = (v * max * 2 + 255) / 510;  // round(v * max / 255)
      if (c.bits == 10) expected = (v << 2) | (v >> 6);
      if (c.bits == 16) expected = v * 257;
      EXPECT_EQ(static_cast<int>(std::lround(back[v * 4] * max)), expected)
          << std::hex << c.internal << " " << v;
    }
  }
}

// Floats are rounded to nearest (even on a tie, in single precision); signed
// bytes map c / 127, negative to 0; unsigned shorts c / 65535.
TEST_F(TextureImageTest, OtherTypesConvertAsMesaConvertsThem) {
  std::vector<GLfloat> f(256 * 4);
  for (int i = 0; i < 256; ++i)
    for (int c = 0; c < 4; ++c) f[i * 4 + c] = i / 255.0f + (c == 1 ? 0.4f / 255 : c == 2 ? -0.4f / 255 : 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 256, 1, 0, GL_RGBA, GL_FLOAT, f.data());
  std::vector<GLubyte> back(256 * 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  for (int i = 0; i < 256; ++i) {
    EXPECT_EQ(back[i * 4], i);
    EXPECT_EQ(back[i * 4 + 1], i);
    EXPECT_EQ(back[i * 4 + 2], i);
  }
  std::vector<GLbyte> b(256 * 4);
  for (int i = 0; i < 256 * 4; ++i) b[i] = static_cast<GLbyte>(i / 4 - 128);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 256, 1, 0, GL_RGBA, GL_BYTE, b.data());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  for (int i = 0; i < 256; ++i) {
    const int c = i - 128;
    const int expected = c <= 0 ? 0 : static_cast<int>(std::nearbyint(c / 127.0f * 255.0f));
    EXPECT_EQ(back[i * 4], expected) << c;
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureImageTest, ErrorsAsMesaGivesThem) {
  static GLubyte px[16 * 16 * 4];
  struct Case {
    GLenum target;
    GLint level, internal;
    GLsizei w, h;
    GLint border;
    GLenum format, type, error;
  } cases[] = {
      {GL_TEXTURE_1D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_ENUM},
      {GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 15, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 14, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_NO_ERROR},
      {GL_TEXTURE_2D, 14, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, -1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, 16385, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, -1, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, GL_NO_ERROR},
      {GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_NO_ERROR},
      {GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_NO_ERROR},
      {GL_TEXTURE_2D, 0, 0, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, 5, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA8, GL_UNSIGNED_BYTE, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_RGBA, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_BGR, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, GL_NO_ERROR},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_BITMAP, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT_5_6_5,
       GL_INVALID_OPERATION},
      {GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE,
       GL_NO_ERROR},
      {GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_VALUE},
      {GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_NO_ERROR},
      {GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_ENUM},
  };
  for (const Case& c : cases) {
    glTexImage2D(c.target, c.level, c.internal, c.w, c.h, c.border, c.format, c.type, px);
    EXPECT_GL_ERROR(c.error) << std::hex << c.target << " level " << std::dec << c.level << " " << std::hex
                             << c.internal << " " << std::dec << c.w << "x" << c.h << " border " << c.border
                             << std::hex << " " << c.format << " " << c.type;
  }
  glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16385, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, px);
  EXPECT_NO_GL_ERROR();
  glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 4, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, px);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2049, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 3, 5, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_NO_GL_ERROR();
  glTexImage3D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexImage3D(GL_TEXTURE_3D, 12, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  GLint v;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &v);
  EXPECT_EQ(v, 16384);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &v);
  EXPECT_EQ(v, 2048);
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &v);
  EXPECT_EQ(v, 16384);
}

// An image larger than llvmpipe allows (1 GiB) is GL_OUT_OF_MEMORY, a proxy
// of it is empty; nothing is allocated.
TEST_F(TextureImageTest, TooLargeIsOutOfMemoryAndAProxyIsEmpty) {
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2048, 2048, 2048, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_OUT_OF_MEMORY);
  EXPECT_EQ(LevelInt(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH), 0);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 2048, 2048, 2048, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH), 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16384, 16384, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 16384);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA16, 16384, 16384, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16385, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 8);
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT), 4);
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE), 8);
  // Errors other than the size still are errors for a proxy.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexImage2D(GL_PROXY_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(LevelInt(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH), 4);
}

// Mesa strips a border before llvmpipe sees the image: the level is the
// inner texels, its border reads 0.
TEST_F(TextureImageTest, BorderIsStripped) {
  GLubyte px[4 * 3 * 4];
  for (int i = 0; i < 4 * 3 * 4; ++i) px[i] = static_cast<GLubyte>(i);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH), 2);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT), 1);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 0, GL_TEXTURE_BORDER), 0);
  GLubyte back[2 * 4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(back[i], px[(4 + 1) * 4 + i]) << i;
}

TEST_F(TextureImageTest, LevelParameterQueries) {
  GLint v = -5;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH, &v);
  EXPECT_EQ(v, 0);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, 3, GL_TEXTURE_INTERNAL_FORMAT), GL_RGBA);  // Mesa, for an undefined level
  glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 15, GL_TEXTURE_WIDTH, &v);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexImage3D(GL_TEXTURE_3D, 1, GL_LUMINANCE, 3, 5, 7, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(LevelInt(GL_TEXTURE_3D, 1, GL_TEXTURE_DEPTH), 7);
  EXPECT_EQ(LevelInt(GL_TEXTURE_3D, 1, GL_TEXTURE_HEIGHT), 5);
  EXPECT_EQ(LevelInt(GL_TEXTURE_3D, 1, GL_TEXTURE_COMPRESSED), GL_FALSE);
  GLfloat f = -1;
  glGetTexLevelParameterfv(GL_TEXTURE_3D, 1, GL_TEXTURE_WIDTH, &f);
  EXPECT_EQ(f, 3.0f);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
