// ARB_texture_float: float internal formats keep values outside [0, 1]
// through upload, glGetTexImage and sampling; the fixed-function texture
// environment works on them unclamped (but for the modes Mesa saturates), and
// the colour is clamped only when written to a fixed-point buffer. Every
// expected value was measured on Mesa 22.3 (llvmpipe); the tests run there too.
#include "api/gl_test_fixture.h"

#include <cstring>
#include <string>

#ifndef GL_RGBA32F_ARB
#include <GL/glext.h>
#endif

namespace glfx_test {
namespace {

using TextureFloatTest = GLTest;

constexpr GLenum kFormats[] = {GL_RGBA32F_ARB, GL_RGB32F_ARB, GL_ALPHA32F_ARB, GL_INTENSITY32F_ARB,
                               GL_LUMINANCE32F_ARB, GL_LUMINANCE_ALPHA32F_ARB, GL_RGBA16F_ARB, GL_RGB16F_ARB,
                               GL_ALPHA16F_ARB, GL_INTENSITY16F_ARB, GL_LUMINANCE16F_ARB,
                               GL_LUMINANCE_ALPHA16F_ARB};

const float kData[16] = {2.0f, -0.5f, 0.3f, 1.5f, 0.1f, 0.2f, 0.3f, 0.4f,
                         1.0f / 3, 65504.f, 70000.f, 1e-8f, 0.5f, -2.f, 3.f, -100.f};

GLint LevelInt(GLenum target, GLenum pname) {
  GLint v = -12345;
  glGetTexLevelParameteriv(target, 0, pname, &v);
  return v;
}

TEST_F(TextureFloatTest, IsAdvertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE((" " + ext + " ").find(" GL_ARB_texture_float "), std::string::npos);
}

// The sizes and component types of each format (a component it has not: 0
// and GL_NONE), the same for a proxy.
TEST_F(TextureFloatTest, ComponentSizesAndTypes) {
  const GLenum sizes[] = {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                          GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
                          GL_TEXTURE_DEPTH_SIZE};
  const GLenum types[] = {GL_TEXTURE_RED_TYPE_ARB, GL_TEXTURE_GREEN_TYPE_ARB, GL_TEXTURE_BLUE_TYPE_ARB,
                          GL_TEXTURE_ALPHA_TYPE_ARB, GL_TEXTURE_LUMINANCE_TYPE_ARB,
                          GL_TEXTURE_INTENSITY_TYPE_ARB, GL_TEXTURE_DEPTH_TYPE_ARB};
  // Which of r, g, b, a, l, i, d each format has.
  const char* has[] = {"rgba", "rgb", "a", "i", "l", "la"};
  for (int f = 0; f < 12; ++f) {
    for (GLenum target : {GL_TEXTURE_2D, GL_PROXY_TEXTURE_2D}) {
      glTexImage2D(target, 0, kFormats[f], 2, 2, 0, GL_RGBA, GL_FLOAT, target == GL_TEXTURE_2D ? kData : nullptr);
      ASSERT_NO_GL_ERROR();
      EXPECT_EQ(LevelInt(target, GL_TEXTURE_INTERNAL_FORMAT), GLint(kFormats[f]));
      const int bits = f < 6 ? 32 : 16;
      for (int c = 0; c < 7; ++c) {
        const bool present = std::strchr(has[f % 6], "rgbalid"[c]) != nullptr;
        EXPECT_EQ(LevelInt(target, sizes[c]), present ? bits : 0) << std::hex << kFormats[f] << " " << c;
        EXPECT_EQ(LevelInt(target, types[c]), present ? GL_FLOAT : GL_NONE) << std::hex << kFormats[f] << " " << c;
      }
    }
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureFloatTest, OtherFormatsAreUnsignedNormalized) {
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, GL_TEXTURE_RED_TYPE_ARB), GL_NONE);  // no image
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_FLOAT, nullptr);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, GL_TEXTURE_RED_TYPE_ARB), GL_UNSIGNED_NORMALIZED_ARB);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, GL_TEXTURE_ALPHA_TYPE_ARB), GL_NONE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, GL_TEXTURE_DEPTH_TYPE_ARB), GL_UNSIGNED_NORMALIZED_ARB);
  EXPECT_EQ(LevelInt(GL_TEXTURE_2D, GL_TEXTURE_RED_TYPE_ARB), GL_NONE);
  EXPECT_NO_GL_ERROR();
  // Depth data into a colour format stays an invalid operation.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 1, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 1, 1, 1, GL_RGBA, GL_FLOAT, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);  // Mesa: no border
}

// glGetTexImage gives the values back unclamped; 16F ones rounded toward
// zero to a half (70000 gives 65504, 1e-8 gives 0); as bytes, clamped.
TEST_F(TextureFloatTest, GetTexImageReturnsUnclampedFloats) {
  struct Case {
    GLenum format;
    float expected[16];
  } cases[] = {
      {GL_RGBA32F_ARB, {2, -0.5f, 0.300000012f, 1.5f, 0.100000001f, 0.200000003f, 0.300000012f, 0.400000006f,
                        0.333333343f, 65504, 70000, 9.99999994e-09f, 0.5f, -2, 3, -100}},
      {GL_RGB32F_ARB, {2, -0.5f, 0.300000012f, 1, 0.100000001f, 0.200000003f, 0.300000012f, 1, 0.333333343f,
                       65504, 70000, 1, 0.5f, -2, 3, 1}},
      {GL_ALPHA32F_ARB, {0, 0, 0, 1.5f, 0, 0, 0, 0.400000006f, 0, 0, 0, 9.99999994e-09f, 0, 0, 0, -100}},
      {GL_INTENSITY32F_ARB, {2, 0, 0, 1, 0.100000001f, 0, 0, 1, 0.333333343f, 0, 0, 1, 0.5f, 0, 0, 1}},
      {GL_LUMINANCE_ALPHA32F_ARB,
       {2, 0, 0, 1.5f, 0.100000001f, 0, 0, 0.400000006f, 0.333333343f, 0, 0, 9.99999994e-09f, 0.5f, 0, 0, -100}},
      {GL_RGBA16F_ARB, {2, -0.5f, 0.299804688f, 1.5f, 0.0999755859f, 0.199951172f, 0.299804688f, 0.399902344f,
                        0.333251953f, 65504, 65504, 0, 0.5f, -2, 3, -100}},
      {GL_LUMINANCE16F_ARB,
       {2, 0, 0, 1, 0.0999755859f, 0, 0, 1, 0.333251953f, 0, 0, 1, 0.5f, 0, 0, 1}},
  };
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, c.format, 2, 2, 0, GL_RGBA, GL_FLOAT, kData);
    float out[16] = {};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
    ASSERT_NO_GL_ERROR();
    for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i], c.expected[i]) << std::hex << c.format << std::dec << " " << i;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 2, 2, 0, GL_RGBA, GL_FLOAT, kData);
  unsigned char ub[16];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  const unsigned char expected[16] = {255, 0, 76, 255, 26, 51, 76, 102, 85, 255, 255, 0, 128, 0, 255, 0};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(ub[i], expected[i]) << i;
}

TEST_F(TextureFloatTest, HalfStorageRoundsTowardZero) {
  const float v[8] = {1.0f + 1.0f / 2048, 1.0f + 3.0f / 2048, 1.0f + 1.0f / 4096, 1.0f + 1.5f / 2048,
                      65519.f, 65520.f, 1e-7f, -3e-8f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F_ARB, 2, 1, 0, GL_RGBA, GL_FLOAT, v);
  float out[8];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
  const float expected[8] = {1, 1.00097656f, 1, 1, 65504, 65504, 5.96046448e-08f, -0.0f};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], expected[i]) << i;
  EXPECT_TRUE(std::signbit(out[7]));
  EXPECT_NO_GL_ERROR();
}

// Bytes go in as b / 255 in float (51 gives 0.200000018, not 0.2).
TEST_F(TextureFloatTest, UnsignedBytesUploadAsUnormFloats) {
  const unsigned char ub[8] = {0, 51, 128, 255, 1, 2, 100, 250};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  float out[8];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
  const float expected[8] = {0, 0.200000018f, 0.501960814f, 1, 0.00392156886f, 0.00784313772f, 0.392156899f,
                             0.980392218f};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], expected[i]) << i;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F_ARB, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
  const float half[8] = {0, 0.199951172f, 0.501953125f, 1, 0.00392150879f, 0.00784301758f, 0.392089844f,
                         0.979980469f};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], half[i]) << i;
  EXPECT_NO_GL_ERROR();
}

// Pixel transfer's scale applies, and nothing clamps after it.
TEST_F(TextureFloatTest, PixelTransferIsNotClamped) {
  glPixelTransferf(GL_RED_SCALE, 3.0f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 2, 2, 0, GL_RGBA, GL_FLOAT, kData);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  float out[16];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
  EXPECT_EQ(out[0], 6.0f);
  EXPECT_EQ(out[4], 0.300000012f);
  EXPECT_EQ(out[8], 1.0f);
  EXPECT_EQ(out[12], 1.5f);
  EXPECT_EQ(out[13], -2.0f);
  EXPECT_NO_GL_ERROR();
}

// GL_HALF_FLOAT_ARB client data: halves in exactly, out rounded to nearest
// even (1 + 3/2048 gives 1 + 2/1024; 65520 and up infinity).
TEST_F(TextureFloatTest, HalfFloatClientData) {
  const GLushort in[8] = {0x3c00, 0xc000, 0x3555, 0x7bff, 0x7c00, 0xfc00, 0x7e00, 0x0001};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F_ARB, 2, 1, 0, GL_RGBA, GL_HALF_FLOAT_ARB, in);
  GLushort out[8];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_HALF_FLOAT_ARB, out);
  ASSERT_NO_GL_ERROR();
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], in[i]) << i;
  float f[4];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 1, 1, 0, GL_RGBA, GL_HALF_FLOAT_ARB, in);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, f);
  EXPECT_EQ(f[0], 1.0f);
  EXPECT_EQ(f[1], -2.0f);
  EXPECT_EQ(f[2], 0.333251953f);
  EXPECT_EQ(f[3], 65504.0f);
  const float v[8] = {1.0f + 1.0f / 2048, 1.0f + 3.0f / 2048, 1.0f + 1.0f / 4096, 1.0f + 1.5f / 2048,
                      65519.f, 70000.f, 1e-7f, -3e-8f};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 2, 1, 0, GL_RGBA, GL_FLOAT, v);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_HALF_FLOAT_ARB, out);
  const GLushort expected[8] = {0x3c00, 0x3c02, 0x3c00, 0x3c01, 0x7bff, 0x7c00, 0x0002, 0x8001};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], expected[i]) << i;
  unsigned char ub[8];
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_HALF_FLOAT_ARB, in);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  const unsigned char bytes[8] = {255, 0, 85, 255, 255, 0, 0, 0};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(ub[i], bytes[i]) << i;
  EXPECT_NO_GL_ERROR();
}

// ---- drawing --------------------------------------------------------------------

const float kTexels[16] = {2.0f, -0.5f, 0.25f, 1.5f, 0.2f, 0.7f, -1.0f, 0.6f,
                           3.0f, 0.1f,  0.9f,  -0.25f, 0.5f, 0.5f, 0.5f, 0.5f};
constexpr GLenum kModes[] = {GL_MODULATE, GL_REPLACE, GL_ADD, GL_DECAL, GL_BLEND, GL_COMBINE};

// A 4x1 float texture over the whole viewport in `mode` (GL_COMBINE:
// ADD_SIGNED colour, MODULATE alpha), colour (0.5, 0.25, 1, 0.5).
void DrawTexturedQuad(GLenum internalFormat, GLenum mode, GLenum filter) {
  glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, 4, 1, 0, GL_RGBA, GL_FLOAT, kTexels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode);
  const float envColor[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
  glColor4f(0.5f, 0.25f, 1.0f, 0.5f);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(-1, -1);
  glTexCoord2f(1, 0);
  glVertex2f(1, -1);
  glTexCoord2f(1, 1);
  glVertex2f(1, 1);
  glTexCoord2f(0, 1);
  glVertex2f(-1, 1);
  glEnd();
  glFinish();
}

// Into an RGBA8 buffer the result is clamped at the end.
TEST_F(TextureFloatTest, EnvironmentIntoFixedPointBuffer) {
  struct Row {
    GLenum format, mode;
    unsigned char px[4][4];
  } rows[] = {
      {GL_RGBA32F_ARB, GL_MODULATE, {{255, 0, 64, 191}, {26, 45, 0, 76}, {255, 6, 230, 0}, {64, 32, 128, 64}}},
      {GL_RGBA32F_ARB, GL_REPLACE, {{255, 0, 64, 255}, {51, 178, 0, 153}, {255, 26, 230, 0}, {128, 128, 128, 128}}},
      {GL_RGBA32F_ARB, GL_ADD, {{255, 0, 255, 191}, {178, 242, 0, 76}, {255, 89, 255, 0}, {255, 191, 255, 64}}},
      {GL_RGBA32F_ARB, GL_DECAL, {{255, 0, 0, 128}, {82, 133, 0, 128}, {0, 73, 255, 128}, {128, 96, 191, 128}}},
      {GL_RGBA32F_ARB, GL_BLEND, {{0, 32, 239, 191}, {115, 108, 255, 76}, {0, 70, 198, 0}, {96, 96, 223, 64}}},
      {GL_RGBA32F_ARB, GL_COMBINE, {{255, 0, 191, 191}, {51, 115, 0, 76}, {255, 0, 255, 0}, {128, 64, 255, 64}}},
      {GL_RGBA16F_ARB, GL_MODULATE, {{255, 0, 64, 191}, {25, 45, 0, 76}, {255, 6, 229, 0}, {64, 32, 128, 64}}},
      {GL_LUMINANCE32F_ARB, GL_BLEND, {{0, 191, 128, 128}, {115, 76, 242, 128}, {0, 255, 64, 128}, {96, 96, 223, 128}}},
      {GL_INTENSITY16F_ARB, GL_MODULATE, {{255, 128, 255, 255}, {25, 13, 51, 25}, {255, 191, 255, 255}, {64, 32, 128, 64}}},
      {GL_ALPHA32F_ARB, GL_COMBINE, {{0, 0, 128, 191}, {0, 0, 128, 76}, {0, 0, 128, 0}, {0, 0, 128, 64}}},
  };
  for (const Row& r : rows) {
    DrawTexturedQuad(r.format, r.mode, GL_NEAREST);
    const unsigned char* p = pixels();
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(p[(8 * kWidth + i * 16 + 8) * 4 + k], r.px[i][k])
            << std::hex << r.format << " " << r.mode << std::dec << " texel " << i << " channel " << k;
  }
  EXPECT_NO_GL_ERROR();
}

// Into an OSMesa GL_FLOAT buffer nothing clamps but the modes Mesa saturates
// (GL_ADD, the combiner's ADD_SIGNED); filtering is done in float.
TEST_F(TextureFloatTest, EnvironmentIntoFloatBuffer) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  ASSERT_NE(ctx, nullptr);
  std::vector<float> buffer(kWidth * kHeight * 4, 0.0f);
  ASSERT_EQ(OSMesaMakeCurrent(ctx, buffer.data(), GL_FLOAT, kWidth, kHeight), GL_TRUE);
  struct Row {
    GLenum format, mode;
    float px[4][4];
  } rows[] = {
      {GL_RGBA32F_ARB, GL_MODULATE,
       {{1, -0.125f, 0.25f, 0.75f}, {0.100000001f, 0.174999997f, -1, 0.300000012f},
        {1.5f, 0.0250000004f, 0.899999976f, -0.125f}, {0.25f, 0.125f, 0.5f, 0.25f}}},
      {GL_RGBA32F_ARB, GL_REPLACE,
       {{2, -0.5f, 0.25f, 1.5f}, {0.200000003f, 0.699999988f, -1, 0.600000024f},
        {3, 0.100000001f, 0.899999976f, -0.25f}, {0.5f, 0.5f, 0.5f, 0.5f}}},
      {GL_RGBA32F_ARB, GL_ADD,
       {{1, 0, 1, 0.75f}, {0.699999988f, 0.949999988f, 0, 0.300000012f}, {1, 0.349999994f, 1, -0.125f},
        {1, 0.75f, 1, 0.25f}}},
      {GL_RGBA32F_ARB, GL_DECAL,
       {{2.75f, -0.875f, -0.125f, 0.5f}, {0.319999993f, 0.519999981f, -0.200000048f, 0.5f},
        {-0.125f, 0.287499994f, 1.02499998f, 0.5f}, {0.5f, 0.375f, 0.75f, 0.5f}}},
      {GL_RGBA32F_ARB, GL_BLEND,
       {{0, 0.125f, 0.9375f, 0.75f}, {0.450000018f, 0.425000012f, 1.25f, 0.300000012f},
        {-0.25f, 0.275000006f, 0.774999976f, -0.125f}, {0.375f, 0.375f, 0.875f, 0.25f}}},
      {GL_RGBA32F_ARB, GL_COMBINE,
       {{1, 0, 0.75f, 0.75f}, {0.199999988f, 0.449999988f, 0, 0.300000012f}, {1, 0, 1, -0.125f},
        {0.5f, 0.25f, 1, 0.25f}}},
      {GL_RGBA16F_ARB, GL_DECAL,
       {{2.75f, -0.875f, -0.125f, 0.5f}, {0.32008791f, 0.519648552f, -0.19921875f, 0.5f},
        {-0.125f, 0.287506104f, 1.02502441f, 0.5f}, {0.5f, 0.375f, 0.75f, 0.5f}}},
      {GL_INTENSITY16F_ARB, GL_BLEND,
       {{0, 0.75f, 0.5f, 1.5f}, {0.450012207f, 0.299987793f, 0.950012207f, 0.599975586f}, {-0.25f, 1, 0.25f, 2},
        {0.375f, 0.375f, 0.875f, 0.75f}}},
      {GL_ALPHA32F_ARB, GL_REPLACE,
       {{0.5f, 0.25f, 1, 1.5f}, {0.5f, 0.25f, 1, 0.600000024f}, {0.5f, 0.25f, 1, -0.25f}, {0.5f, 0.25f, 1, 0.5f}}},
  };
  for (const Row& r : rows) {
    DrawTexturedQuad(r.format, r.mode, GL_NEAREST);
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(buffer[(8 * kWidth + i * 16 + 8) * 4 + k], r.px[i][k])
            << std::hex << r.format << " " << r.mode << std::dec << " texel " << i << " channel " << k;
  }
  DrawTexturedQuad(GL_RGBA32F_ARB, GL_REPLACE, GL_LINEAR);
  const float linear[5][4] = {{1.296875f, -0.03125f, 0.3671875f, 1.03125f},
                              {1.765625f, -0.34375f, 0.2890625f, 1.34375f},
                              {1.71875f, -0.3125f, 0.0546875f, 1.359375f},
                              {1.15625f, 0.0625000224f, -0.3359375f, 1.078125f},
                              {0.59375006f, 0.43750003f, -0.7265625f, 0.796875f}};
  for (int n = 0; n < 5; ++n)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(buffer[(8 * kWidth + n * 5) * 4 + k], linear[n][k]) << n << " " << k;
  EXPECT_NO_GL_ERROR();
  OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight);
  OSMesaDestroyContext(ctx);
}


// A float RGBA or RGB texture is a complete colour attachment and is drawn
// into unclamped (the framebuffer is in float mode); its 16F texels are the
// half float renderbuffer's.
TEST_F(TextureFloatTest, DrawsIntoFloatTextureAttachments) {
  // The commands through OSMesaGetProcAddress (GL 2.1's headers lack them).
  constexpr GLenum kFramebuffer = 0x8D40, kColorAttachment0 = 0x8CE0, kComplete = 0x8CD5;
  auto genFramebuffers = reinterpret_cast<void (*)(GLsizei, GLuint*)>(OSMesaGetProcAddress("glGenFramebuffersEXT"));
  auto deleteFramebuffers =
      reinterpret_cast<void (*)(GLsizei, const GLuint*)>(OSMesaGetProcAddress("glDeleteFramebuffersEXT"));
  auto bindFramebuffer = reinterpret_cast<void (*)(GLenum, GLuint)>(OSMesaGetProcAddress("glBindFramebufferEXT"));
  auto framebufferTexture2D = reinterpret_cast<void (*)(GLenum, GLenum, GLenum, GLuint, GLint)>(
      OSMesaGetProcAddress("glFramebufferTexture2DEXT"));
  auto checkStatus = reinterpret_cast<GLenum (*)(GLenum)>(OSMesaGetProcAddress("glCheckFramebufferStatusEXT"));
  ASSERT_TRUE(genFramebuffers && deleteFramebuffers && bindFramebuffer && framebufferTexture2D && checkStatus);
  GLuint src = 0;
  glGenTextures(1, &src);
  glBindTexture(GL_TEXTURE_2D, src);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F_ARB, 4, 1, 0, GL_RGBA, GL_FLOAT, kTexels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  struct Case {
    GLenum format;
    float pixel1[4], pixel4[4];
  } cases[] = {
      {GL_RGBA32F_ARB, {0.774999976f, -0.149999991f, -0.0625f, 0.637499988f}, {1.14999998f, 0.1875f, 0.424999982f, -0.018749997f}},
      {GL_RGBA16F_ARB, {0.774902344f, -0.149902344f, -0.0625f, 0.637207031f}, {1.14941406f, 0.1875f, 0.424804688f, -0.018737793f}},
      {GL_RGB32F_ARB, {0.774999976f, -0.149999991f, -0.0625f, 1}, {1.14999998f, 0.1875f, 0.424999982f, 1}},
      {GL_RGB16F_ARB, {0.774902344f, -0.149902344f, -0.0625f, 1}, {1.14941406f, 0.1875f, 0.424804688f, 1}},
  };
  for (const Case& c : cases) {
    GLuint tex = 0, fb = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, c.format, 8, 4, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    genFramebuffers(1, &fb);
    bindFramebuffer(kFramebuffer, fb);
    framebufferTexture2D(kFramebuffer, kColorAttachment0, GL_TEXTURE_2D, tex, 0);
    ASSERT_EQ(checkStatus(kFramebuffer), kComplete) << std::hex << c.format;
    glViewport(0, 0, 8, 4);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, src);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.5f, 0.75f, 1.0f, 0.5f);
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0, 0);
    glVertex2f(-1, -1);
    glTexCoord2f(1, 0);
    glVertex2f(1, -1);
    glTexCoord2f(1, 1);
    glVertex2f(1, 1);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    float read[8 * 4 * 4], got[8 * 4 * 4];
    glReadPixels(0, 0, 8, 4, GL_RGBA, GL_FLOAT, read);
    bindFramebuffer(kFramebuffer, 0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, got);
    ASSERT_NO_GL_ERROR();
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(read[k], (k == 0 ? 0.25f : k == 1 ? 0.5f : k == 2 ? 0.75f : 1.0f)) << k;  // the clear colour
      EXPECT_EQ(read[4 + k], c.pixel1[k]) << std::hex << c.format << std::dec << " " << k;
      EXPECT_EQ(read[16 + k], c.pixel4[k]) << std::hex << c.format << std::dec << " " << k;
    }
    for (int k = 0; k < 8 * 4 * 4; ++k) EXPECT_EQ(got[k], read[k]) << std::hex << c.format << std::dec << " " << k;
    deleteFramebuffers(1, &fb);
    glDeleteTextures(1, &tex);
  }
}

}  // namespace
}  // namespace glfx_test
