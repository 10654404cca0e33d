// glReadPixels and glGetTexImage with the packed pixel types (GL 2.1 §3.6.4
// table 3.8, §4.3.2; EXT_packed_pixels), and glDrawPixels / glTexImage2D
// from them: random colours in the window's 8-bit, 16-bit, float and 5-6-5
// buffers and in framebuffer objects, read back as each packed type with each
// format it allows, with pixel transfer, the pack parameters, a pack buffer
// and GL_MESA_pack_invert. The expected values are FNV-1a hashes of what Mesa
// 22.3.6's llvmpipe gives (probed; MESA_FACTS.md "Packed pixel types").
#include "gl_test_fixture.h"

#include <cstdio>
#include <string>

#ifndef GL_PACK_INVERT_MESA
#define GL_PACK_INVERT_MESA 0x8758
#endif

using namespace glfx_test;

namespace {

constexpr int kW = 24, kH = 12;

uint32_t fnv(const void* data, size_t n, uint32_t h = 2166136261u) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 16777619u;
  }
  return h;
}

struct PackedCase {
  GLenum type;
  int bytes;
  bool threeFields;
};
const PackedCase kTypes[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, true},          {GL_UNSIGNED_BYTE_2_3_3_REV, 1, true},
    {GL_UNSIGNED_SHORT_5_6_5, 2, true},         {GL_UNSIGNED_SHORT_5_6_5_REV, 2, true},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, false},      {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, false},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, false},      {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, false},
    {GL_UNSIGNED_INT_10_10_10_2, 4, false},     {GL_UNSIGNED_INT_2_10_10_10_REV, 4, false},
    {GL_UNSIGNED_INT_8_8_8_8, 4, false},        {GL_UNSIGNED_INT_8_8_8_8_REV, 4, false},
};

uint32_t g_seed = 1;
uint32_t nextRandom() {
  g_seed = g_seed * 1103515245u + 12345u;
  return g_seed >> 8;
}

// kW x kH random colours drawn at the origin: bytes, or floats in [0, 1].
void drawRandom(bool floats, uint32_t seed) {
  g_seed = seed;
  glViewport(0, 0, kW, kH);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRasterPos2i(0, 0);
  if (floats) {
    std::vector<float> v(kW * kH * 4);
    // Multiples of 1/1024: Mesa's glDrawPixels keeps them in a float buffer.
    for (float& x : v) x = static_cast<float>(nextRandom() % 1025) / 1024.0f;
    glDrawPixels(kW, kH, GL_RGBA, GL_FLOAT, v.data());
  } else {
    std::vector<unsigned char> v(kW * kH * 4);
    for (unsigned char& x : v) x = static_cast<unsigned char>(nextRandom());
    glDrawPixels(kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, v.data());
  }
}

// Every packed type with every format it allows, read from the current read
// buffer (kW x kH, with the current pack state) into memory filled with 0xA5;
// the hash of all of them. `detail` gets one hash per read.
uint32_t readAllPacked(std::string& detail, size_t bytesPerRead = kW * kH * 16) {
  uint32_t h = 2166136261u;
  char buf[64];
  for (const PackedCase& c : kTypes) {
    const GLenum formats[2] = {c.threeFields ? GLenum(GL_RGB) : GLenum(GL_RGBA), GL_BGRA};
    for (int k = 0; k < (c.threeFields ? 1 : 2); ++k) {
      std::vector<unsigned char> out(bytesPerRead, 0xA5);
      glReadPixels(0, 0, kW, kH, formats[k], c.type, out.data());
      const GLenum e = glGetError();
      const uint32_t one = fnv(out.data(), out.size()) ^ e;
      std::snprintf(buf, sizeof buf, " %04x/%04x:%08x", c.type, formats[k], one);
      detail += buf;
      h = fnv(&one, 4, h);
    }
  }
  return h;
}

template <typename F>
void load(F*& f, const char* name) {
  f = reinterpret_cast<F*>(OSMesaGetProcAddress(name));
}

class ReadPixelsPackedTest : public GLTest {};

}  // namespace

TEST_F(ReadPixelsPackedTest, WrongFormatIsAnInvalidOperation) {
  unsigned char out[64];
  for (const PackedCase& c : kTypes) {
    SCOPED_TRACE(testing::Message() << "type 0x" << std::hex << c.type);
    const GLenum bad[] = {GL_RED, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_BGR,
                          c.threeFields ? GLenum(GL_RGBA) : GLenum(GL_RGB),
                          c.threeFields ? GLenum(GL_BGRA) : GLenum(GL_ALPHA)};
    for (GLenum f : bad) {
      glReadPixels(0, 0, 1, 1, f, c.type, out);
      EXPECT_GL_ERROR(GL_INVALID_OPERATION) << "format 0x" << std::hex << f;
    }
    glReadPixels(0, 0, 1, 1, c.threeFields ? GL_RGB : GL_RGBA, c.type, out);
    EXPECT_NO_GL_ERROR();
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, c.type, out);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, c.type, out);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  }
}

TEST_F(ReadPixelsPackedTest, FromTheWindow) {
  struct Case {
    const char* name;
    bool floats;
    uint32_t expected;
  };
  const Case cases[] = {{"bytes", false, 3179947321u}, {"floats", true, 3786104063u}};
  for (const Case& c : cases) {
    drawRandom(c.floats, 99);
    std::string detail;
    EXPECT_EQ(readAllPacked(detail), c.expected) << c.name << detail;
  }
}

TEST_F(ReadPixelsPackedTest, WithPixelTransfer) {
  drawRandom(false, 7);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_SCALE, 0.7f);
  glPixelTransferf(GL_BLUE_BIAS, 0.25f);
  glPixelTransferf(GL_ALPHA_SCALE, 1.5f);
  std::string detail;
  EXPECT_EQ(readAllPacked(detail), 4106659300u) << detail;
}

TEST_F(ReadPixelsPackedTest, WithPackParametersAndInvert) {
  drawRandom(false, 11);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPixelStorei(GL_PACK_ROW_LENGTH, kW + 3);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  std::string detail;
  EXPECT_EQ(readAllPacked(detail), 2117494083u) << detail;
  // (Mesa writes before the pointer when inverting with skips: none here.)
  glPixelStorei(GL_PACK_INVERT_MESA, GL_TRUE);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  detail.clear();
  EXPECT_EQ(readAllPacked(detail), 134759243u) << "inverted" << detail;
}

TEST_F(ReadPixelsPackedTest, IntoAPackBufferOfTheRightSize) {
  drawRandom(false, 5);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
  const int w = 5, h = 3;
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  for (const PackedCase& c : kTypes) {
    SCOPED_TRACE(testing::Message() << "type 0x" << std::hex << c.type);
    // Rows of 5 pixels padded to 4 bytes; the last one ends after pixel 6 (one skipped).
    const size_t row = (5 * c.bytes + 3) / 4 * 4, size = 2 * row + 6 * c.bytes;
    const GLenum format = c.threeFields ? GL_RGB : GL_RGBA;
    glBufferData(GL_PIXEL_PACK_BUFFER, size - 1, nullptr, GL_STREAM_READ);
    glReadPixels(0, 0, w, h, format, c.type, nullptr);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    std::vector<unsigned char> fill(size, 0xA5);
    glBufferData(GL_PIXEL_PACK_BUFFER, size, fill.data(), GL_STREAM_READ);
    glReadPixels(0, 0, w, h, format, c.type, nullptr);
    EXPECT_NO_GL_ERROR();
    std::vector<unsigned char> direct(size, 0xA5), got(size);
    glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, size, got.data());
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glReadPixels(0, 0, w, h, format, c.type, direct.data());
    EXPECT_EQ(got, direct);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
  EXPECT_NO_GL_ERROR();
}

TEST(ReadPixelsPackedBufferTypeTest, FromOSMesaBuffersOfOtherTypes) {
  struct Case {
    GLenum format, type;
    int bytesPerPixel;
    bool floats;
    uint32_t expected;
  };
  const Case cases[] = {
      {OSMESA_RGBA, GL_UNSIGNED_SHORT, 8, false, 692198139u}, {OSMESA_RGBA, GL_UNSIGNED_SHORT, 8, true, 4133840820u},
      {OSMESA_RGBA, GL_FLOAT, 16, false, 692198139u},
      {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 2, true, 863968214u},
      {OSMESA_BGRA, GL_UNSIGNED_BYTE, 4, false, 692198139u},  // not RGBA8: its 10-bit fields from floats
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "buffer type 0x" << std::hex << c.type << (c.floats ? " floats" : " bytes"));
    OSMesaContext ctx = OSMesaCreateContextExt(c.format, 0, 0, 0, NULL);
    ASSERT_NE(ctx, nullptr);
    std::vector<unsigned char> mem(kW * kH * c.bytesPerPixel, 0);
    ASSERT_EQ(OSMesaMakeCurrent(ctx, mem.data(), c.type, kW, kH), GL_TRUE);
    drawRandom(c.floats, 3);
    std::string detail;
    EXPECT_EQ(readAllPacked(detail), c.expected) << detail;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }
}

TEST_F(ReadPixelsPackedTest, FromFramebufferObjects) {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*deleteFramebuffers)(GLsizei, const GLuint*);
  void (*bindFramebuffer)(GLenum, GLuint);
  void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
  void (*genRenderbuffers)(GLsizei, GLuint*);
  void (*deleteRenderbuffers)(GLsizei, const GLuint*);
  void (*bindRenderbuffer)(GLenum, GLuint);
  void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
  load(genFramebuffers, "glGenFramebuffers");
  load(deleteFramebuffers, "glDeleteFramebuffers");
  load(bindFramebuffer, "glBindFramebuffer");
  load(framebufferRenderbuffer, "glFramebufferRenderbuffer");
  load(genRenderbuffers, "glGenRenderbuffers");
  load(deleteRenderbuffers, "glDeleteRenderbuffers");
  load(bindRenderbuffer, "glBindRenderbuffer");
  load(renderbufferStorage, "glRenderbufferStorage");
  ASSERT_NE(renderbufferStorage, nullptr);
  struct Case {
    GLenum internalFormat;
    uint32_t expected;
  };
  const Case cases[] = {
      {0x8058, 2034648721u},  // GL_RGBA8
      {0x8051, 3720786024u},  // GL_RGB8
      {0x8056, 3504089127u},  // GL_RGBA4
      {0x8057, 1924023083u},  // GL_RGB5_A1
      {0x8D62, 2946991188u},  // GL_RGB565
      {0x805B, 3041040839u},  // GL_RGBA16
      {0x8059, 3351175054u},  // GL_RGB10_A2
      {0x8814, 3041040839u},  // GL_RGBA32F
      {0x881A, 3534414266u},  // GL_RGBA16F
      {0x8054, 3720786024u},  // GL_RGB16
      {0x805A, 3041040839u},  // GL_RGBA12
      {0x8050, 2136506966u},  // GL_RGB5
      {0x804F, 4050076486u},  // GL_RGB4
      {0x8055, 3504089127u},  // GL_RGBA2
      {0x8815, 3720786024u},  // GL_RGB32F
      {0x881B, 2469816178u},  // GL_RGB16F
      {0x8C43, 2034648721u},  // GL_SRGB8_ALPHA8
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "renderbuffer 0x" << std::hex << c.internalFormat);
    GLuint fb = 0, rb = 0;
    genFramebuffers(1, &fb);
    bindFramebuffer(0x8D40, fb);
    genRenderbuffers(1, &rb);
    bindRenderbuffer(0x8D41, rb);
    renderbufferStorage(0x8D41, c.internalFormat, kW, kH);
    framebufferRenderbuffer(0x8D40, 0x8CE0, 0x8D41, rb);
    drawRandom(false, 13);
    std::string detail;
    EXPECT_EQ(readAllPacked(detail), c.expected) << detail;
    bindFramebuffer(0x8D40, 0);
    deleteRenderbuffers(1, &rb);
    deleteFramebuffers(1, &fb);
    EXPECT_NO_GL_ERROR();
  }
}

TEST_F(ReadPixelsPackedTest, GetTexImage) {
  struct Case {
    GLenum internalFormat;
    uint32_t expected;
  };
  const Case cases[] = {{GL_RGBA8, 875313729u}, {GL_RGB5_A1, 2636283248u}, {GL_RGBA16, 4240274134u},
                        {GL_RGB8, 1449917910u},           {GL_RGBA4, 3502512166u},           {GL_R3_G3_B2, 58071467u},
                        {GL_RGB10_A2, 116188510u},       {GL_RGB16, 443302351u},           {GL_LUMINANCE8, 3376758409u},
                        {GL_LUMINANCE8_ALPHA8, 253785909u}, {GL_INTENSITY8, 3376758409u},   {GL_ALPHA8, 4022442369u},
                        {GL_LUMINANCE16, 2024651317u},    {GL_RGB5, 647158524u},            {GL_LUMINANCE4_ALPHA4, 1342421868u}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "internal format 0x" << std::hex << c.internalFormat);
    g_seed = 21;
    std::vector<float> v(kW * kH * 4);
    for (float& x : v) x = static_cast<float>(nextRandom() % 1000001) / 1000000.0f;
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, c.internalFormat, kW, kH, 0, GL_RGBA, GL_FLOAT, v.data());
    uint32_t h = 2166136261u;
    std::string detail;
    char buf[64];
    for (const PackedCase& t : kTypes) {
      const GLenum formats[2] = {t.threeFields ? GLenum(GL_RGB) : GLenum(GL_RGBA), GL_BGRA};
      for (int k = 0; k < (t.threeFields ? 1 : 2); ++k) {
        std::vector<unsigned char> out(kW * kH * 4, 0xA5);
        glGetTexImage(GL_TEXTURE_2D, 0, formats[k], t.type, out.data());
        const uint32_t one = fnv(out.data(), out.size()) ^ glGetError();
        std::snprintf(buf, sizeof buf, " %04x/%04x:%08x", t.type, formats[k], one);
        detail += buf;
        h = fnv(&one, 4, h);
      }
    }
    EXPECT_EQ(h, c.expected) << detail;
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, v.data());
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    glDeleteTextures(1, &tex);
  }
}

// The unpack direction: random packed pixels drawn with glDrawPixels and
// given to glTexImage2D, read back as bytes.
TEST_F(ReadPixelsPackedTest, DrawPixelsAndTexImageFromPackedTypes) {
  uint32_t hDraw = 2166136261u, hTex = 2166136261u;
  std::string detail;
  char buf[64];
  for (const PackedCase& t : kTypes) {
    const GLenum formats[2] = {t.threeFields ? GLenum(GL_RGB) : GLenum(GL_RGBA), GL_BGRA};
    for (int k = 0; k < (t.threeFields ? 1 : 2); ++k) {
      g_seed = 31 + t.type;
      std::vector<unsigned char> in(kW * kH * 4);
      for (unsigned char& x : in) x = static_cast<unsigned char>(nextRandom());
      glViewport(0, 0, kW, kH);
      glMatrixMode(GL_PROJECTION);
      glLoadIdentity();
      glOrtho(0, kW, 0, kH, -1, 1);
      glRasterPos2i(0, 0);
      glDrawPixels(kW, kH, formats[k], t.type, in.data());
      std::vector<unsigned char> out(kW * kH * 4);
      glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
      const uint32_t one = fnv(out.data(), out.size()) ^ glGetError();
      hDraw = fnv(&one, 4, hDraw);
      GLuint tex = 0;
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kW, kH, 0, formats[k], t.type, in.data());
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
      const uint32_t two = fnv(out.data(), out.size()) ^ glGetError();
      hTex = fnv(&two, 4, hTex);
      glDeleteTextures(1, &tex);
      std::snprintf(buf, sizeof buf, " %04x/%04x:%08x,%08x", t.type, formats[k], one, two);
      detail += buf;
    }
  }
  EXPECT_EQ(hDraw, 2957126063u) << detail;
  EXPECT_EQ(hTex, 2957126063u) << detail;
}
