// Drawing into framebuffer objects of every colour format this library draws
// into (renderbuffers and textures): the status, the sizes reported, and the
// pixels read back with glReadPixels and glGetTexImage after a clear, a
// blended smooth triangle and an unblended one. The expected values are
// FNV-1a hashes of what Mesa 22.3.6's llvmpipe gives (probed; MESA_FACTS.md
// "Framebuffer objects").
#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

constexpr GLenum kFramebuffer = 0x8D40, kRenderbuffer = 0x8D41, kColor0 = 0x8CE0, kComplete = 0x8CD5;

uint32_t fnv(const void* data, size_t n) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  uint32_t h = 2166136261u;
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 16777619u;
  }
  return h;
}

struct FormatCase {
  bool renderbuffer;  // else a 2D texture
  GLenum internalFormat;
  int sizes[4];  // red, green, blue, alpha
  // glReadPixels as GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_FLOAT, and
  // glGetTexImage as GL_UNSIGNED_SHORT; 0: not compared.
  uint32_t readUbyte, readUshort, readFloat, texImageUshort;
};

// clang-format off
const FormatCase kCases[] = {
    {true, 0x8058, {8, 8, 8, 8}, 0xec22a789u, 0x09abfc1du, 0xac092f60u, 0u},  // GL_RGBA8
    {true, 0x8051, {8, 8, 8, 0}, 0xbda075cdu, 0x4f676471u, 0x35caa80du, 0u},  // GL_RGB8
    {true, 0x8056, {4, 4, 4, 4}, 0x950b1800u, 0x96ce3c1bu, 0xcdbed51du, 0u},  // GL_RGBA4
    {true, 0x8057, {5, 5, 5, 1}, 0x9614ea2cu, 0xe1bdbf3au, 0xe8fea98bu, 0u},  // GL_RGB5_A1
    {true, 0x8D62, {5, 6, 5, 0}, 0x16c64abcu, 0xe98fea38u, 0x2f936126u, 0u},  // GL_RGB565
    {true, 0x805B, {16, 16, 16, 16}, 0x7454d310u, 0x49b70651u, 0x0aa9c3d0u, 0u},  // GL_RGBA16
    {true, 0x8054, {16, 16, 16, 0}, 0xa26ff562u, 0x5b7e9397u, 0x6d102b80u, 0u},  // GL_RGB16
    {true, 0x805A, {16, 16, 16, 16}, 0x7454d310u, 0x49b70651u, 0x0aa9c3d0u, 0u},  // GL_RGBA12
    {true, 0x8050, {5, 5, 5, 0}, 0x0ded3720u, 0x5d212df2u, 0xb6688d5fu, 0u},  // GL_RGB5
    {true, 0x804F, {4, 4, 4, 0}, 0xfe927532u, 0x27062d53u, 0xb55f3b78u, 0u},  // GL_RGB4
    {true, 0x8055, {4, 4, 4, 4}, 0x950b1800u, 0x96ce3c1bu, 0xcdbed51du, 0u},  // GL_RGBA2
    // Float: every bit of the interpolation (llvmpipe's, y up in an object).
    {true, 0x8814, {32, 32, 32, 32}, 0x8797beacu, 0xc971aafeu, 0xf8e5f55au, 0u},  // GL_RGBA32F
    {true, 0x8815, {32, 32, 32, 0}, 0x8976bcfau, 0xf6cd264fu, 0xcfb997ebu, 0u},   // GL_RGB32F
    // Half floats: the bytes (HalfFloatStoreRoundsTowardZero checks the halves).
    {true, 0x881A, {16, 16, 16, 16}, 0xd685266bu, 0u, 0u, 0u},  // GL_RGBA16F
    {true, 0x881B, {16, 16, 16, 0}, 0x813f8142u, 0u, 0u, 0u},   // GL_RGB16F
    {true, 0x8C43, {8, 8, 8, 8}, 0xec22a789u, 0x09abfc1du, 0xac092f60u, 0u},  // GL_SRGB8_ALPHA8
    {false, 0x8058, {8, 8, 8, 8}, 0xec22a789u, 0x09abfc1du, 0xac092f60u, 0x09abfc1du},
    {false, 0x8051, {8, 8, 8, 0}, 0xbda075cdu, 0x4f676471u, 0x35caa80du, 0x4f676471u},
    {false, 0x8056, {4, 4, 4, 4}, 0x950b1800u, 0x96ce3c1bu, 0xcdbed51du, 0x96ce3c1bu},
    {false, 0x8057, {5, 5, 5, 1}, 0x9614ea2cu, 0xe1bdbf3au, 0xe8fea98bu, 0xe1bdbf3au},
    {false, 0x1907, {5, 6, 5, 0}, 0x16c64abcu, 0xe98fea38u, 0x2f936126u, 0xe98fea38u},  // GL_RGB + 5_6_5
    {false, 0x8050, {5, 5, 5, 0}, 0x0ded3720u, 0x5d212df2u, 0xb6688d5fu, 0x5d212df2u},
    {false, 0x804F, {4, 4, 4, 0}, 0xfe927532u, 0x27062d53u, 0xb55f3b78u, 0x27062d53u},
    {false, 0x8055, {4, 4, 4, 4}, 0x950b1800u, 0x96ce3c1bu, 0xcdbed51du, 0x96ce3c1bu},
    {false, 0x805B, {16, 16, 16, 16}, 0x7454d310u, 0x49b70651u, 0x0aa9c3d0u, 0x49b70651u},
    {false, 0x8054, {16, 16, 16, 0}, 0xa26ff562u, 0x5b7e9397u, 0x6d102b80u, 0x5b7e9397u},
    {false, 0x805A, {16, 16, 16, 16}, 0x7454d310u, 0x49b70651u, 0x0aa9c3d0u, 0x49b70651u},
    {false, 0x8C43, {8, 8, 8, 8}, 0xec22a789u, 0x09abfc1du, 0xac092f60u, 0x09abfc1du},  // GL_SRGB8_ALPHA8
    {false, 0x8C41, {8, 8, 8, 0}, 0xbda075cdu, 0x4f676471u, 0x35caa80du, 0x4f676471u},  // GL_SRGB8
    {true, 0x822B, {8, 8, 0, 0}, 0x822933deu, 0xf0d82dd7u, 0x464d73cbu, 0u},  // GL_RG8: (R, G, 0, 1)
    {true, 0x822C, {16, 16, 0, 0}, 0x5a34fd5au, 0x5f5311d6u, 0x3b996edau, 0u},  // GL_RG16
    // 3-3-2: ((b >> n) * (2^n - 1) + 2^(7 - n)) >> (8 - n) from the 8-bit blend.
    {true, 0x2A10, {3, 3, 2, 0}, 0xbc31cbfcu, 0x2e16f2b3u, 0xfda829e9u, 0u},   // GL_R3_G3_B2
    {false, 0x2A10, {3, 3, 2, 0}, 0xbc31cbfcu, 0x2e16f2b3u, 0xfda829e9u, 0x2e16f2b3u},  // GL_R3_G3_B2
    // 10 bits: blended in llvmpipe's 16-bit type, cut to 10 (and 2) bits.
    {true, 0x8059, {10, 10, 10, 2}, 0x445cd771u, 0x7198e7f2u, 0x562d7e32u, 0u},   // GL_RGB10_A2
    {true, 0x8052, {10, 10, 10, 0}, 0xd9f036f9u, 0xa7f63ad6u, 0x50fc113au, 0u},   // GL_RGB10
    {false, 0x8059, {10, 10, 10, 2}, 0x445cd771u, 0x7198e7f2u, 0x562d7e32u, 0x7198e7f2u},  // GL_RGB10_A2
    {false, 0x8052, {10, 10, 10, 0}, 0xd9f036f9u, 0xa7f63ad6u, 0x50fc113au, 0xa7f63ad6u},  // GL_RGB10
    // Luminance-alpha textures: red goes into the luminance, read back as
    // (L, 0, 0, A); the luminance reports no size.
    {false, 0x8045, {0, 0, 0, 8}, 0x987c007fu, 0xdee99a0du, 0x6f50d625u, 0xdee99a0du},    // GL_LUMINANCE8_ALPHA8
    {false, 0x8043, {0, 0, 0, 4}, 0xe7315ee8u, 0x96955087u, 0xa1043e6du, 0x96955087u},  // GL_LUMINANCE4_ALPHA4
    {false, 0x8048, {0, 0, 0, 16}, 0x2bfbadc9u, 0x74ba3e29u, 0x0ff6e4e9u, 0x74ba3e29u},   // GL_LUMINANCE16_ALPHA16
};
// clang-format on

constexpr int kW = 16, kH = 16;

template <typename F>
void load(F*& f, const char* name) {
  f = reinterpret_cast<F*>(OSMesaGetProcAddress(name));
}

// A clear, a blended smooth triangle over it and an unblended one.
void drawScene() {
  glViewport(0, 0, kW, kH);
  glClearColor(0.3f, 0.6f, 0.9f, 0.55f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor4f(1, 0.2f, 0.1f, 0.9f);
  glVertex2f(-0.9f, -0.9f);
  glColor4f(0.1f, 1, 0.3f, 0.4f);
  glVertex2f(0.9f, -0.7f);
  glColor4f(0.2f, 0.3f, 1, 0.7f);
  glVertex2f(-0.6f, 0.95f);
  glEnd();
  glDisable(GL_BLEND);
  glBegin(GL_TRIANGLES);
  glColor4f(0.77f, 0.13f, 0.51f, 0.33f);
  glVertex2f(0.2f, 0.2f);
  glColor4f(0.01f, 0.99f, 0.49f, 0.66f);
  glVertex2f(1, 0.3f);
  glColor4f(0.5f, 0.5f, 0.02f, 1);
  glVertex2f(0.6f, 1);
  glEnd();
}

GLenum externalFormat(GLenum internal) {
  switch (internal) {
    case GL_RGBA8: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA2: case GL_RGBA16: case GL_RGBA12: case 0x8C43:
    case GL_RGB10_A2:
      return GL_RGBA;
    default: return GL_RGB;
  }
}

class FramebufferFormatTest : public GLTest {};

// A level past the base level can be drawn into only when the texture has
// its whole mipmap chain down to the maximum level (Mesa, probed), whatever
// its filters; the base level always.
TEST_F(FramebufferFormatTest, LevelsPastTheBaseNeedTheMipmapChain) {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*bindFramebuffer)(GLenum, GLuint);
  GLenum (*checkFramebufferStatus)(GLenum);
  void (*framebufferTexture2D)(GLenum, GLenum, GLenum, GLuint, GLint);
  void (*framebufferTexture3D)(GLenum, GLenum, GLenum, GLuint, GLint, GLint);
  load(genFramebuffers, "glGenFramebuffers");
  load(bindFramebuffer, "glBindFramebuffer");
  load(checkFramebufferStatus, "glCheckFramebufferStatus");
  load(framebufferTexture2D, "glFramebufferTexture2D");
  load(framebufferTexture3D, "glFramebufferTexture3D");
  ASSERT_NE(framebufferTexture3D, nullptr);
  constexpr GLenum kIncompleteAttachment = 0x8CD6;
  GLuint fb = 0;
  genFramebuffers(1, &fb);
  bindFramebuffer(kFramebuffer, fb);
  GLuint tex[3];
  glGenTextures(3, tex);
  // 16x16 with levels 0, 1 and 3: level 1 incomplete, the base complete.
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  for (int level : {0, 1, 3}) glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, 16 >> level, 16 >> level, 0, GL_RGBA,
                                           GL_UNSIGNED_BYTE, nullptr);
  framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex[0], 1);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex[0], 0);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
  // The chain ends at the maximum level.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
  framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex[0], 1);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
  // Every level: complete at each.
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  for (int level = 0; level < 5; ++level)
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, 16 >> level, 16 >> level, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex[1], 4);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
  // 3D, 8x8x4 with levels 0 and 1: level 1 incomplete at every layer; with
  // the whole chain, level 1 layers 0 and 1 complete, layer 2 past its depth.
  glBindTexture(GL_TEXTURE_3D, tex[2]);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 8, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexImage3D(GL_TEXTURE_3D, 1, GL_RGBA8, 4, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  framebufferTexture3D(kFramebuffer, kColor0, GL_TEXTURE_3D, tex[2], 1, 1);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  glTexImage3D(GL_TEXTURE_3D, 2, GL_RGBA8, 2, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexImage3D(GL_TEXTURE_3D, 3, GL_RGBA8, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
  framebufferTexture3D(kFramebuffer, kColor0, GL_TEXTURE_3D, tex[2], 1, 2);
  EXPECT_EQ(checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  bindFramebuffer(kFramebuffer, 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferFormatTest, DrawIntoEveryColourFormat) {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*deleteFramebuffers)(GLsizei, const GLuint*);
  void (*bindFramebuffer)(GLenum, GLuint);
  GLenum (*checkFramebufferStatus)(GLenum);
  void (*framebufferTexture2D)(GLenum, GLenum, GLenum, GLuint, GLint);
  void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
  void (*getFramebufferAttachmentParameteriv)(GLenum, GLenum, GLenum, GLint*);
  void (*genRenderbuffers)(GLsizei, GLuint*);
  void (*deleteRenderbuffers)(GLsizei, const GLuint*);
  void (*bindRenderbuffer)(GLenum, GLuint);
  void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
  void (*getRenderbufferParameteriv)(GLenum, GLenum, GLint*);
  load(genFramebuffers, "glGenFramebuffers");
  load(deleteFramebuffers, "glDeleteFramebuffers");
  load(bindFramebuffer, "glBindFramebuffer");
  load(checkFramebufferStatus, "glCheckFramebufferStatus");
  load(framebufferTexture2D, "glFramebufferTexture2D");
  load(framebufferRenderbuffer, "glFramebufferRenderbuffer");
  load(getFramebufferAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
  load(genRenderbuffers, "glGenRenderbuffers");
  load(deleteRenderbuffers, "glDeleteRenderbuffers");
  load(bindRenderbuffer, "glBindRenderbuffer");
  load(renderbufferStorage, "glRenderbufferStorage");
  load(getRenderbufferParameteriv, "glGetRenderbufferParameteriv");
  ASSERT_NE(getRenderbufferParameteriv, nullptr);
  for (const FormatCase& c : kCases) {
    SCOPED_TRACE(testing::Message() << (c.renderbuffer ? "renderbuffer 0x" : "texture 0x") << std::hex
                                    << c.internalFormat);
    GLuint fb = 0, rb = 0, tex = 0;
    genFramebuffers(1, &fb);
    bindFramebuffer(kFramebuffer, fb);
    if (c.renderbuffer) {
      genRenderbuffers(1, &rb);
      bindRenderbuffer(kRenderbuffer, rb);
      renderbufferStorage(kRenderbuffer, c.internalFormat, kW, kH);
      framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, rb);
      for (int k = 0; k < 4; ++k) {
        GLint v = -1;
        getRenderbufferParameteriv(kRenderbuffer, 0x8D50 + k, &v);  // GL_RENDERBUFFER_RED_SIZE...
        EXPECT_EQ(v, c.sizes[k]) << "channel " << k;
      }
    } else {
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      const GLenum type = c.internalFormat == GL_RGB ? GL_UNSIGNED_SHORT_5_6_5 : GL_UNSIGNED_BYTE;
      glTexImage2D(GL_TEXTURE_2D, 0, c.internalFormat, kW, kH, 0, externalFormat(c.internalFormat), type,
                   nullptr);
      framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 0);
    }
    for (int k = 0; k < 4; ++k) {
      GLint v = -1;
      getFramebufferAttachmentParameteriv(kFramebuffer, kColor0, 0x8212 + k, &v);  // _RED_SIZE...
      EXPECT_EQ(v, c.sizes[k]) << "attachment channel " << k;
      EXPECT_EQ(GetInt(GL_RED_BITS + k), c.sizes[k]) << "GL_*_BITS " << k;
    }
    ASSERT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
    drawScene();
    std::vector<GLubyte> ub(kW * kH * 4);
    std::vector<GLushort> us(kW * kH * 4);
    std::vector<GLfloat> fl(kW * kH * 4);
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, ub.data());
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_SHORT, us.data());
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_FLOAT, fl.data());
    EXPECT_EQ(fnv(ub.data(), ub.size()), c.readUbyte) << "pixel (2,2) " << int(ub[136]) << " " << int(ub[137])
                                                       << " " << int(ub[138]) << " " << int(ub[139]);
    if (c.readUshort) EXPECT_EQ(fnv(us.data(), us.size() * 2), c.readUshort);
    if (c.readFloat) EXPECT_EQ(fnv(fl.data(), fl.size() * 4), c.readFloat);
    bindFramebuffer(kFramebuffer, 0);
    if (!c.renderbuffer) {
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, us.data());
      EXPECT_EQ(fnv(us.data(), us.size() * 2), c.texImageUshort);
      glDeleteTextures(1, &tex);
    } else {
      deleteRenderbuffers(1, &rb);
    }
    deleteFramebuffers(1, &fb);
    EXPECT_NO_GL_ERROR();
  }
}

// Half-float renderbuffers (Mesa, probed): clears and blends keep values
// outside [0, 1]; the store rounds toward zero, denormal halves too, and
// saturates at the largest half (65504); the framebuffer is in float mode,
// so glReadPixels of floats does not clamp (nor does it on GL_RGBA32F).
// Points at pixel centres: no interpolation, the same on any orientation.
TEST_F(FramebufferFormatTest, HalfFloatStoreRoundsTowardZero) {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*bindFramebuffer)(GLenum, GLuint);
  GLenum (*checkFramebufferStatus)(GLenum);
  void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
  void (*genRenderbuffers)(GLsizei, GLuint*);
  void (*bindRenderbuffer)(GLenum, GLuint);
  void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
  void (*blendEquation)(GLenum);
  load(genFramebuffers, "glGenFramebuffers");
  load(bindFramebuffer, "glBindFramebuffer");
  load(checkFramebufferStatus, "glCheckFramebufferStatus");
  load(framebufferRenderbuffer, "glFramebufferRenderbuffer");
  load(genRenderbuffers, "glGenRenderbuffers");
  load(bindRenderbuffer, "glBindRenderbuffer");
  load(renderbufferStorage, "glRenderbufferStorage");
  load(blendEquation, "glBlendEquation");
  ASSERT_NE(blendEquation, nullptr);
  constexpr GLenum kFloatMode = 0x8820;  // GL_RGBA_FLOAT_MODE_ARB
  EXPECT_EQ(GetInt(kFloatMode), 0);
  for (GLenum internal : {GLenum(0x881A), GLenum(0x8814)}) {  // GL_RGBA16F, GL_RGBA32F
    SCOPED_TRACE(testing::Message() << "renderbuffer 0x" << std::hex << internal);
    const bool half = internal == 0x881A;
    GLuint fb = 0, rb = 0;
    genFramebuffers(1, &fb);
    bindFramebuffer(kFramebuffer, fb);
    genRenderbuffers(1, &rb);
    bindRenderbuffer(kRenderbuffer, rb);
    renderbufferStorage(kRenderbuffer, internal, 4, 1);
    framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, rb);
    ASSERT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
    EXPECT_EQ(GetInt(kFloatMode), 1);
    glViewport(0, 0, 4, 1);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 4, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(60000.0f, 1e-6f, -3e-7f, 2.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_COLOR, GL_ONE);  // pixel 0: d * s + d
    glBegin(GL_POINTS);
    glColor4f(1, 1, 0.5f, 1);
    glVertex2f(0.5f, 0.5f);
    glEnd();
    glBlendFunc(GL_ONE, GL_ONE);  // pixel 1: d - s
    blendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glBegin(GL_POINTS);
    glColor4f(0.3f, 0.7f, 1, 1);
    glVertex2f(1.5f, 0.5f);
    glEnd();
    blendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glBegin(GL_POINTS);  // pixel 2: unblended
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    glVertex2f(2.5f, 0.5f);
    glEnd();
    float f[16];
    GLubyte ub[16];
    glReadPixels(0, 0, 4, 1, GL_RGBA, GL_FLOAT, f);
    glReadPixels(0, 0, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    if (half) {
      const float expected[12] = {65504.0f, 0x1p-19f, -0x1.cp-22f, 4.0f, 59968.0f, -0x1.664p-1f, -1.0f, 1.0f,
                                  0x1.998p-4f, 0x1.998p-3f, 0x1.33p-2f, 0x1.998p-2f};
      for (int i = 0; i < 12; ++i) EXPECT_EQ(f[i], expected[i]) << "float " << i;
    } else {
      EXPECT_EQ(f[0], 120000.0f);
      EXPECT_EQ(f[5], 1e-6f - 0.7f);
      EXPECT_EQ(f[8], 0.1f);
    }
    const GLubyte bytes[8] = {255, 0, 0, 255, 255, 0, 0, 255};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(ub[i], bytes[i]) << "byte " << i;
    bindFramebuffer(kFramebuffer, 0);
    EXPECT_EQ(GetInt(kFloatMode), 0);
    EXPECT_NO_GL_ERROR();
  }
}

// A clear of part of the buffer (scissored) is drawn by Mesa as a quad, so
// its colour is stored as a fragment's; a clear of the whole buffer rounds
// half up from float (probed): 0.2 clears RGB10_A2 red to 205 of 1023 but a
// scissored 0.2 stores rint(0.2 * 65535) >> 6 = 204; 0.3 clears RGBA16 to
// 19661, scissored to 19660.
TEST_F(FramebufferFormatTest, ScissoredClearIsStoredAsAFragment) {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*bindFramebuffer)(GLenum, GLuint);
  GLenum (*checkFramebufferStatus)(GLenum);
  void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
  void (*genRenderbuffers)(GLsizei, GLuint*);
  void (*bindRenderbuffer)(GLenum, GLuint);
  void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
  load(genFramebuffers, "glGenFramebuffers");
  load(bindFramebuffer, "glBindFramebuffer");
  load(checkFramebufferStatus, "glCheckFramebufferStatus");
  load(framebufferRenderbuffer, "glFramebufferRenderbuffer");
  load(genRenderbuffers, "glGenRenderbuffers");
  load(bindRenderbuffer, "glBindRenderbuffer");
  load(renderbufferStorage, "glRenderbufferStorage");
  ASSERT_NE(renderbufferStorage, nullptr);
  struct Case {
    GLenum internal;
    float value;
    GLushort whole, scissored;  // red read back as GL_UNSIGNED_SHORT
  };
  // 205 and 204 of 1023 read rint(v / 1023 * 65535).
  for (const Case& c : {Case{GL_RGB10_A2, 0.2f, 13133, 13069}, Case{GL_RGBA16, 0.3f, 19661, 19660}}) {
    SCOPED_TRACE(testing::Message() << "renderbuffer 0x" << std::hex << c.internal);
    GLuint fb = 0, rb = 0;
    genFramebuffers(1, &fb);
    bindFramebuffer(kFramebuffer, fb);
    genRenderbuffers(1, &rb);
    bindRenderbuffer(kRenderbuffer, rb);
    renderbufferStorage(kRenderbuffer, c.internal, 4, 1);
    framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, rb);
    ASSERT_EQ(checkFramebufferStatus(kFramebuffer), kComplete);
    glClearColor(c.value, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 0, 1, 1);
    glClearColor(0.9f, 0, 0, 1);  // first something else, then the value
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(c.value, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    GLushort us[8];
    glReadPixels(0, 0, 2, 1, GL_RGBA, GL_UNSIGNED_SHORT, us);
    EXPECT_EQ(us[0], c.whole);
    EXPECT_EQ(us[4], c.scissored);
    bindFramebuffer(kFramebuffer, 0);
    EXPECT_NO_GL_ERROR();
  }
}

}  // namespace

namespace {

// glGetFramebufferAttachmentParameteriv on the window system's framebuffer
// (Mesa, probed): its colour, depth and stencil buffers with their sizes,
// a right buffer GL_NONE, and the errors.
TEST_F(FramebufferFormatTest, WindowFramebufferAttachmentQueries) {
  void (*getFramebufferAttachmentParameteriv)(GLenum, GLenum, GLenum, GLint*);
  load(getFramebufferAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
  ASSERT_NE(getFramebufferAttachmentParameteriv, nullptr);
  constexpr GLenum kObjectType = 0x8CD0, kObjectName = 0x8CD1, kTextureLevel = 0x8CD2, kEncoding = 0x8210,
                   kComponentType = 0x8211, kRedSize = 0x8212, kDepthSize = 0x8216, kStencilSize = 0x8217;
  auto query = [&](GLenum target, GLenum attachment, GLenum pname) {
    GLint v = -7;
    getFramebufferAttachmentParameteriv(target, attachment, pname, &v);
    return v;
  };
  const GLint depthBits = GetInt(GL_DEPTH_BITS), stencilBits = GetInt(GL_STENCIL_BITS);
  for (GLenum buffer : {GLenum(GL_FRONT_LEFT), GLenum(GL_BACK_LEFT), GLenum(GL_FRONT), GLenum(GL_BACK)}) {
    EXPECT_EQ(query(kFramebuffer, buffer, kObjectType), 0x8218);  // GL_FRAMEBUFFER_DEFAULT
    EXPECT_EQ(query(kFramebuffer, buffer, kEncoding), GL_LINEAR);
    EXPECT_EQ(query(kFramebuffer, buffer, kComponentType), 0x8C17);  // GL_UNSIGNED_NORMALIZED
    for (int k = 0; k < 4; ++k) EXPECT_EQ(query(kFramebuffer, buffer, kRedSize + k), GetInt(GL_RED_BITS + k));
    EXPECT_EQ(query(kFramebuffer, buffer, kDepthSize), 0);
    EXPECT_NO_GL_ERROR();
    query(kFramebuffer, buffer, kObjectName);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    query(kFramebuffer, buffer, kTextureLevel);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(query(0x8CA9, GL_BACK_LEFT, kRedSize), 8);  // GL_DRAW_FRAMEBUFFER
  EXPECT_EQ(query(0x8CA8, GL_FRONT_LEFT, kRedSize), 8);  // GL_READ_FRAMEBUFFER
  if (depthBits > 0) {
    // The depth and stencil attachments both tell the depth and stencil bits.
    for (GLenum buffer : {GLenum(GL_DEPTH), GLenum(GL_STENCIL)}) {
      if (buffer == GL_STENCIL && stencilBits == 0) continue;
      EXPECT_EQ(query(kFramebuffer, buffer, kObjectType), 0x8218);
      EXPECT_EQ(query(kFramebuffer, buffer, kRedSize), 0);
      EXPECT_EQ(query(kFramebuffer, buffer, kDepthSize), depthBits);
      EXPECT_EQ(query(kFramebuffer, buffer, kStencilSize), stencilBits);
    }
  }
  // No right buffer: GL_NONE, then GL_INVALID_OPERATION.
  EXPECT_EQ(query(kFramebuffer, GL_FRONT_RIGHT, kObjectType), GL_NONE);
  query(kFramebuffer, GL_FRONT_RIGHT, kRedSize);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  query(kFramebuffer, kColor0, kObjectType);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
