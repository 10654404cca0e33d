// Depth-stencil textures (EXT_packed_depth_stencil: internal formats
// GL_DEPTH_STENCIL and GL_DEPTH24_STENCIL8): which targets and client data
// they take, what glGetTexImage and glGetTexLevelParameter give back,
// glCopyTexImage from the depth-stencil buffer, and a depth-stencil texture
// drawn into through a framebuffer object then sampled as a depth texture.
// The values are Mesa 22.3.6's llvmpipe's (probed; MESA_FACTS.md
// "Depth-stencil textures"). Mesa takes GL_TEXTURE_RECTANGLE too; this
// library has no rectangle textures.
#include <vector>

#include "gl_test_fixture.h"
#include "stencil_context.h"

using namespace glfx_test;

namespace {

constexpr GLenum kDepthStencil = 0x84F9, kUnsignedInt24_8 = 0x84FA, kDepth24Stencil8 = 0x88F0;
constexpr GLenum kFloat32UnsignedInt24_8Rev = 0x8DAD, kTextureStencilSize = 0x88F1;
constexpr GLenum kFramebuffer = 0x8D40, kRenderbuffer = 0x8D41;
constexpr GLenum kColor0 = 0x8CE0, kDepthAttachment = 0x8D00, kStencilAttachment = 0x8D20,
                 kDepthStencilAttachment = 0x821A;
constexpr GLenum kComplete = 0x8CD5, kIncompleteAttachment = 0x8CD6, kUnsupported = 0x8CDD;
constexpr GLenum kObjectName = 0x8CD1, kComponentType = 0x8211, kDepthSize = 0x8216, kStencilSize = 0x8217;
constexpr GLenum kUnsignedNormalized = 0x8C17;

// FNV-1a over bytes: the rendered images are compared by it.
uint32_t Checksum(const void* data, size_t n) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  uint32_t h = 2166136261u;
  for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 16777619u;
  return h;
}

struct Fbo {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*bindFramebuffer)(GLenum, GLuint);
  GLenum (*checkFramebufferStatus)(GLenum);
  void (*framebufferTexture1D)(GLenum, GLenum, GLenum, GLuint, GLint);
  void (*framebufferTexture2D)(GLenum, GLenum, GLenum, GLuint, GLint);
  void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
  void (*getFramebufferAttachmentParameteriv)(GLenum, GLenum, GLenum, GLint*);
  void (*genRenderbuffers)(GLsizei, GLuint*);
  void (*bindRenderbuffer)(GLenum, GLuint);
  void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
};

template <typename F>
void load(F*& f, const char* name) {
  f = reinterpret_cast<F*>(OSMesaGetProcAddress(name));
}

// A context with a 24-bit depth and 8-bit stencil buffer.
class DepthStencilTextureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(context_.ok());
    load(f.genFramebuffers, "glGenFramebuffers");
    load(f.bindFramebuffer, "glBindFramebuffer");
    load(f.checkFramebufferStatus, "glCheckFramebufferStatus");
    load(f.framebufferTexture1D, "glFramebufferTexture1D");
    load(f.framebufferTexture2D, "glFramebufferTexture2D");
    load(f.framebufferRenderbuffer, "glFramebufferRenderbuffer");
    load(f.getFramebufferAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
    load(f.genRenderbuffers, "glGenRenderbuffers");
    load(f.bindRenderbuffer, "glBindRenderbuffer");
    load(f.renderbufferStorage, "glRenderbufferStorage");
    ASSERT_NE(f.framebufferTexture2D, nullptr);
    ASSERT_NE(f.getFramebufferAttachmentParameteriv, nullptr);
    ASSERT_NE(f.renderbufferStorage, nullptr);
    glMatrixMode(GL_PROJECTION);  // the context's one-unit-a-pixel projection undone
    glLoadIdentity();
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }

  GLuint texture(GLenum target) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(target, t);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
  }
  GLint level(GLenum target, GLenum pname) {
    GLint v = -7;
    glGetTexLevelParameteriv(target, 0, pname, &v);
    return v;
  }
  GLint attachmentParam(GLenum point, GLenum pname) {
    GLint v = -7;
    f.getFramebufferAttachmentParameteriv(kFramebuffer, point, pname, &v);
    return v;
  }

  StencilContext context_{24, 8};
  Fbo f{};
};

// 16 texels: depth i * 0x111111, stencil i * 16 + 3.
std::vector<GLuint> Ramp() {
  std::vector<GLuint> d(16);
  for (GLuint i = 0; i < 16; ++i) d[i] = (i * 0x111111u) << 8 | (i * 16 + 3);
  return d;
}

TEST_F(DepthStencilTextureTest, TargetsAndErrorsAsMesaGivesThem) {
  const std::vector<GLuint> d = Ramp();
  for (GLenum internal : {kDepth24Stencil8, kDepthStencil}) {
    texture(GL_TEXTURE_1D);
    glTexImage1D(GL_TEXTURE_1D, 0, internal, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
    EXPECT_NO_GL_ERROR();
    texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
    EXPECT_NO_GL_ERROR();
    texture(GL_TEXTURE_CUBE_MAP);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, internal, 2, 2, 0, kDepthStencil, kUnsignedInt24_8,
                 d.data());
    EXPECT_NO_GL_ERROR();
    texture(GL_TEXTURE_3D);
    glTexImage3D(GL_TEXTURE_3D, 0, internal, 2, 2, 2, 0, kDepthStencil, kUnsignedInt24_8, d.data());
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);  // no 3D depth textures
  }

  texture(GL_TEXTURE_2D);
  struct Case {
    GLint internal;
    GLenum format, type, error;
  };
  const Case cases[] = {
      {GLint(kDepth24Stencil8), kDepthStencil, GL_UNSIGNED_INT, GL_INVALID_ENUM},
      {GLint(kDepth24Stencil8), kDepthStencil, GL_FLOAT, GL_INVALID_ENUM},
      {GLint(kDepth24Stencil8), kDepthStencil, GL_UNSIGNED_BYTE, GL_INVALID_ENUM},
      {GLint(kDepth24Stencil8), kDepthStencil, kFloat32UnsignedInt24_8Rev, GL_NO_ERROR},
      {GLint(kDepth24Stencil8), GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {GLint(kDepth24Stencil8), GL_RGBA, kUnsignedInt24_8, GL_INVALID_OPERATION},
      {GLint(kDepth24Stencil8), GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, GL_NO_ERROR},
      {GLint(kDepth24Stencil8), GL_DEPTH_COMPONENT, GL_FLOAT, GL_NO_ERROR},
      {GLint(kDepth24Stencil8), GL_DEPTH_COMPONENT, kUnsignedInt24_8, GL_INVALID_OPERATION},
      {GLint(kDepth24Stencil8), GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {GLint(kDepthStencil), GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, GL_NO_ERROR},
      {GL_RGBA, kDepthStencil, kUnsignedInt24_8, GL_INVALID_OPERATION},
      {GL_RGBA8, kDepthStencil, kUnsignedInt24_8, GL_INVALID_OPERATION},
      {GL_LUMINANCE, kDepthStencil, kUnsignedInt24_8, GL_INVALID_OPERATION},
      {GL_DEPTH_COMPONENT24, kDepthStencil, kUnsignedInt24_8, GL_NO_ERROR},
      {GL_DEPTH_COMPONENT, kDepthStencil, kUnsignedInt24_8, GL_NO_ERROR},
      {GL_DEPTH_COMPONENT16, kDepthStencil, kUnsignedInt24_8, GL_NO_ERROR},
      {GL_RGBA, GL_RGBA, kUnsignedInt24_8, GL_INVALID_OPERATION},
      {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, kUnsignedInt24_8, GL_INVALID_OPERATION},
  };
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, c.internal, 2, 2, 0, c.format, c.type, d.data());
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.internal << " " << c.format << " " << c.type;
  }

  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  EXPECT_NO_GL_ERROR();
  const Case subs[] = {
      {0, kDepthStencil, kUnsignedInt24_8, GL_NO_ERROR},
      {0, kDepthStencil, GL_UNSIGNED_INT, GL_INVALID_ENUM},
      {0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, GL_NO_ERROR},
      {0, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NO_ERROR},
      {0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {0, GL_RGBA, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},
      {0, GL_RGBA, kUnsignedInt24_8, GL_INVALID_OPERATION},
  };
  for (const Case& c : subs) {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, c.format, c.type, d.data());
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.format << " " << c.type;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, d.data());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, kDepthStencil, kUnsignedInt24_8, d.data());
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLuint out[16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d.data());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, kDepthStencil, kUnsignedInt24_8, d.data());
  EXPECT_NO_GL_ERROR();  // a depth texture takes the depth of depth-stencil data
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);  // but does not give it back as such
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, GL_UNSIGNED_INT, out);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

TEST_F(DepthStencilTextureTest, LevelParametersAndProxies) {
  texture(GL_TEXTURE_2D);
  struct Case {
    GLint internal;
    GLenum format;
    GLint reported, depth, stencil;
  };
  const Case cases[] = {
      {GLint(kDepth24Stencil8), kDepthStencil, GLint(kDepth24Stencil8), 24, 8},
      {GLint(kDepthStencil), kDepthStencil, GLint(kDepthStencil), 24, 8},
      {GLint(kDepthStencil), GL_DEPTH_COMPONENT, GLint(kDepthStencil), 24, 8},
      {GL_DEPTH_COMPONENT24, kDepthStencil, GL_DEPTH_COMPONENT24, 24, 0},
      {GL_DEPTH_COMPONENT16, kDepthStencil, GL_DEPTH_COMPONENT16, 16, 0},
      {GL_DEPTH_COMPONENT, kDepthStencil, GL_DEPTH_COMPONENT, 24, 0},
      {GL_RGBA8, GL_RGBA, GL_RGBA8, 0, 0},
  };
  for (const Case& c : cases) {
    const GLenum type = c.format == kDepthStencil ? kUnsignedInt24_8
                        : c.format == GL_RGBA     ? GL_UNSIGNED_BYTE
                                                  : GL_UNSIGNED_INT;
    glTexImage2D(GL_TEXTURE_2D, 0, c.internal, 2, 2, 0, c.format, type, nullptr);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(level(GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), c.reported);
    EXPECT_EQ(level(GL_TEXTURE_2D, GL_TEXTURE_DEPTH_SIZE), c.depth) << std::hex << c.internal;
    EXPECT_EQ(level(GL_TEXTURE_2D, kTextureStencilSize), c.stencil) << std::hex << c.internal;
    EXPECT_EQ(level(GL_TEXTURE_2D, GL_TEXTURE_RED_SIZE), c.format == GL_RGBA ? 8 : 0);
  }
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(level(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH), 4);
  EXPECT_EQ(level(GL_PROXY_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), GLint(kDepth24Stencil8));
  EXPECT_EQ(level(GL_PROXY_TEXTURE_2D, GL_TEXTURE_DEPTH_SIZE), 24);
  EXPECT_EQ(level(GL_PROXY_TEXTURE_2D, kTextureStencilSize), 8);
  glTexImage1D(GL_PROXY_TEXTURE_1D, 0, kDepth24Stencil8, 4, 0, kDepthStencil, kUnsignedInt24_8, nullptr);
  EXPECT_EQ(level(GL_PROXY_TEXTURE_1D, GL_TEXTURE_WIDTH), 4);
  glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8,
               nullptr);
  EXPECT_EQ(level(GL_PROXY_TEXTURE_CUBE_MAP, GL_TEXTURE_WIDTH), 4);
  EXPECT_NO_GL_ERROR();
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, kDepth24Stencil8, 2, 2, 2, 0, kDepthStencil, kUnsignedInt24_8, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(level(GL_PROXY_TEXTURE_3D, GL_TEXTURE_WIDTH), 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

TEST_F(DepthStencilTextureTest, UploadsAndReadBacks) {
  const std::vector<GLuint> d = Ramp();
  texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  GLuint out[16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i], d[i]) << i;
  // The depth as GL_UNSIGNED_INT: through a float, scaled in double.
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out);
  EXPECT_NO_GL_ERROR();
  const GLuint asUint[16] = {0x00000000, 0x1111111f, 0x2222223f, 0x3333333f, 0x4444447f, 0x5555557f,
                             0x6666667f, 0x7777777f, 0x888888ff, 0x999999ff, 0xaaaaaaff, 0xbbbbbbff,
                             0xccccccff, 0xddddddff, 0xeeeeeeff, 0xffffffff};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i], asUint[i]) << i;
  GLushort us[16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, us);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(us[i], 0x1111 * i) << i;
  GLfloat fl[16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fl);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(fl[i], static_cast<float>(i * 0x111111) / 16777215.0f) << i;
  GLubyte st[16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
  EXPECT_NO_GL_ERROR();
  for (int i = 0; i < 16; ++i) EXPECT_EQ(st[i], i * 16 + 3) << i;

  // A sub-image of depth-stencil data; then depth data replaces the depth.
  const GLuint sub[4] = {0x12345678, 0x9abcdef0, 0x0000ff01, 0xffffff80};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 2, 2, kDepthStencil, kUnsignedInt24_8, sub);
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(out[9], sub[0]);
  EXPECT_EQ(out[10], sub[1]);
  EXPECT_EQ(out[13], sub[2]);
  EXPECT_EQ(out[14], sub[3]);
  EXPECT_EQ(out[8], d[8]);
  EXPECT_EQ(out[15], d[15]);
  const GLfloat depths[4] = {0.0f, 0.25f, 0.5f, 1.0f};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  EXPECT_NO_GL_ERROR();
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  // The depth only: Mesa leaves the stencil of such texels undefined.
  EXPECT_EQ(out[0] >> 8, 0u);
  EXPECT_EQ(out[1] >> 8, 0x3fffffu);  // 0.25 * (2^24 - 1) truncated
  EXPECT_EQ(out[4] >> 8, 0x7fffffu);
  EXPECT_EQ(out[5] >> 8, 0xffffffu);
  EXPECT_EQ(out[2], d[2]);

  // Pixel transfer: the depth scale on the depth (stored truncated), the
  // index offset on the stencil.
  glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i] & 0xff, (d[i] & 0xff) + 1) << i;
  EXPECT_EQ(out[1] >> 8, 0x088888u);
  EXPECT_EQ(out[2] >> 8, 0x111111u);
  EXPECT_EQ(out[15] >> 8, 0x7fffffu);
  // GL_FLOAT_32_UNSIGNED_INT_24_8_REV: a float depth (clamped, stored
  // truncated), then a word whose low byte is the stencil.
  const GLuint f32[8] = {0x3e800000u, 0x12, 0x3f000000u, 0x34, 0x3fc00000u, 0x56, 0xbf800000u, 0x78};
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 2, 2, 0, kDepthStencil, kFloat32UnsignedInt24_8Rev, f32);
  EXPECT_NO_GL_ERROR();
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(out[0], 0x3fffff12u);
  EXPECT_EQ(out[1], 0x7fffff34u);
  EXPECT_EQ(out[2], 0xffffff56u);
  EXPECT_EQ(out[3], 0x00000078u);
  GLuint undefined = 0;
  glGenTextures(1, &undefined);
  glBindTexture(GL_TEXTURE_2D, undefined);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
  EXPECT_NO_GL_ERROR();  // an undefined level: nothing written, no error
  texture(GL_TEXTURE_2D);

  // Compiled into a display list, the data is copied at compile time.
  std::vector<GLuint> listed = Ramp();
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, listed.data());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, kDepthStencil, kUnsignedInt24_8, sub);
  glEndList();
  listed.assign(16, 0);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glCallList(list);
  EXPECT_NO_GL_ERROR();
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(out[0], sub[0]);
  for (int i = 1; i < 16; ++i) EXPECT_EQ(out[i], d[i]) << i;
  glDeleteLists(list, 1);

  // A depth texture from depth-stencil data keeps the depth.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(out[i], asUint[i]) << i;
  EXPECT_NO_GL_ERROR();
}

TEST_F(DepthStencilTextureTest, NoGenerateMipmap) {
  void (*generateMipmap)(GLenum) = nullptr;
  load(generateMipmap, "glGenerateMipmap");
  ASSERT_NE(generateMipmap, nullptr);
  const std::vector<GLuint> d = Ramp();
  texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  generateMipmap(GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(level(GL_TEXTURE_2D, GL_TEXTURE_WIDTH), 4);
  GLint w = -7;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 0);
}

TEST_F(DepthStencilTextureTest, CopyTexImageFromTheDepthStencilBuffer) {
  glViewport(0, 0, 16, 16);
  glClearDepth(0.25);
  glClearStencil(0x5a);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glStencilFunc(GL_ALWAYS, 0x33, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glRectf(-1, -1, 0, 0);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  texture(GL_TEXTURE_2D);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 4, 4, 8, 8, 0);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(level(GL_TEXTURE_2D, kTextureStencilSize), 8);
  GLuint out[64] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(out[0], 0x80000033u);   // inside the rectangle: depth 0.5, stencil 0x33
  EXPECT_EQ(out[63], 0x4000005au);  // the cleared values
  EXPECT_EQ(out[3], 0x80000033u);
  EXPECT_EQ(out[4], 0x4000005au);
  const uint32_t image = Checksum(out, sizeof out);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 0, 0, 4, 4);
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(out[4 * 8 + 4], 0x80000033u);
  EXPECT_EQ(out[7 * 8 + 7], 0x80000033u);
  EXPECT_NE(Checksum(out, sizeof out), image);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, kDepthStencil, 4, 4, 8, 8, 0);
  EXPECT_EQ(level(GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), GLint(kDepthStencil));
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(Checksum(out, sizeof out), image);
  texture(GL_TEXTURE_1D);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, kDepth24Stencil8, 6, 6, 8, 0);
  glGetTexImage(GL_TEXTURE_1D, 0, kDepthStencil, kUnsignedInt24_8, out);
  EXPECT_EQ(out[0], 0x80000033u);
  EXPECT_EQ(out[1], 0x80000033u);
  EXPECT_EQ(out[2], 0x4000005au);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DepthStencilTextureTest, AttachmentsAndCompleteness) {
  const GLuint ds = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 16, 16, 0, kDepthStencil, kUnsignedInt24_8, nullptr);
  const GLuint color = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const GLuint d24 = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, color, 0);
  f.framebufferTexture2D(kFramebuffer, kDepthAttachment, GL_TEXTURE_2D, ds, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_EQ(attachmentParam(kDepthAttachment, kDepthSize), 24);
  EXPECT_EQ(attachmentParam(kDepthAttachment, kStencilSize), 8);
  EXPECT_EQ(GetInt(GL_DEPTH_BITS), 24);
  EXPECT_EQ(GetInt(GL_STENCIL_BITS), 0);  // at the depth attachment only
  f.framebufferTexture2D(kFramebuffer, kStencilAttachment, GL_TEXTURE_2D, ds, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_EQ(GetInt(GL_STENCIL_BITS), 8);
  EXPECT_EQ(attachmentParam(kStencilAttachment, kDepthSize), 24);
  EXPECT_EQ(attachmentParam(kStencilAttachment, kStencilSize), 8);
  EXPECT_EQ(attachmentParam(kStencilAttachment, kComponentType), GLint(kUnsignedNormalized));
  EXPECT_EQ(attachmentParam(kDepthAttachment, kComponentType), GLint(kUnsignedNormalized));
  EXPECT_EQ(attachmentParam(kDepthStencilAttachment, kObjectName), GLint(ds));
  EXPECT_EQ(attachmentParam(kDepthStencilAttachment, kStencilSize), 8);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(attachmentParam(kDepthStencilAttachment, kComponentType), -7);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);

  GLuint fb2 = 0;
  f.genFramebuffers(1, &fb2);
  f.bindFramebuffer(kFramebuffer, fb2);
  f.framebufferTexture2D(kFramebuffer, kDepthStencilAttachment, GL_TEXTURE_2D, ds, 0);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(attachmentParam(kStencilAttachment, kObjectName), GLint(ds));
  EXPECT_EQ(attachmentParam(kDepthAttachment, kObjectName), GLint(ds));
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);  // depth-stencil only
  f.framebufferTexture2D(kFramebuffer, kDepthStencilAttachment, GL_TEXTURE_2D, d24, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);  // no stencil in it
  f.framebufferTexture2D(kFramebuffer, kDepthStencilAttachment, GL_TEXTURE_2D, 0, 0);
  f.framebufferTexture2D(kFramebuffer, kStencilAttachment, GL_TEXTURE_2D, ds, 0);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, color, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);  // stencil only
  f.framebufferTexture2D(kFramebuffer, kStencilAttachment, GL_TEXTURE_2D, d24, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  f.framebufferTexture2D(kFramebuffer, kStencilAttachment, GL_TEXTURE_2D, 0, 0);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, ds, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, color, 0);
  f.framebufferTexture2D(kFramebuffer, kDepthAttachment, GL_TEXTURE_2D, d24, 0);
  f.framebufferTexture2D(kFramebuffer, kStencilAttachment, GL_TEXTURE_2D, ds, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kUnsupported);  // two buffers
  GLuint rb = 0;
  f.genRenderbuffers(1, &rb);
  f.bindRenderbuffer(kRenderbuffer, rb);
  f.renderbufferStorage(kRenderbuffer, kDepth24Stencil8, 16, 16);
  f.framebufferTexture2D(kFramebuffer, kDepthAttachment, GL_TEXTURE_2D, ds, 0);
  f.framebufferRenderbuffer(kFramebuffer, kStencilAttachment, kRenderbuffer, rb);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kUnsupported);
  EXPECT_EQ(attachmentParam(kStencilAttachment, kComponentType), GLint(kUnsignedNormalized));
  GLuint s8 = 0;
  f.genRenderbuffers(1, &s8);
  f.bindRenderbuffer(kRenderbuffer, s8);
  f.renderbufferStorage(kRenderbuffer, 0x8D48, 16, 16);  // GL_STENCIL_INDEX8
  f.framebufferRenderbuffer(kFramebuffer, kStencilAttachment, kRenderbuffer, s8);
  EXPECT_EQ(attachmentParam(kStencilAttachment, kComponentType), 0x8222);  // GL_INDEX
  f.framebufferRenderbuffer(kFramebuffer, kStencilAttachment, kRenderbuffer, 0);
  f.framebufferTexture2D(kFramebuffer, kDepthAttachment, GL_TEXTURE_2D, 0, 0);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, 0, 0);
  const GLuint ds1 = texture(GL_TEXTURE_1D);
  glTexImage1D(GL_TEXTURE_1D, 0, kDepth24Stencil8, 16, 0, kDepthStencil, kUnsignedInt24_8, nullptr);
  f.framebufferTexture1D(kFramebuffer, kDepthStencilAttachment, GL_TEXTURE_1D, ds1, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_NO_GL_ERROR();
  f.bindFramebuffer(kFramebuffer, 0);
}

// A depth-stencil texture at the stencil attachment alone: the object has
// no depth buffer (GL_DEPTH_BITS 0, GL_DEPTH_TEST draws as if disabled),
// the stencil test works on the texture's stencil and keeps its depth.
TEST_F(DepthStencilTextureTest, StencilAttachmentAloneHasNoDepth) {
  std::vector<GLuint> d(64, 0x80000000u | 7);
  const GLuint ds = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 8, 8, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  const GLuint color = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, color, 0);
  f.framebufferTexture2D(kFramebuffer, kStencilAttachment, GL_TEXTURE_2D, ds, 0);
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_EQ(GetInt(GL_DEPTH_BITS), 0);
  EXPECT_EQ(GetInt(GL_STENCIL_BITS), 8);
  glViewport(0, 0, 8, 8);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // no depth to clear
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 7, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glColor3f(1, 1, 1);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  GLubyte px[4] = {};
  glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);
  GLuint z = 0;
  glReadPixels(4, 4, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.bindFramebuffer(kFramebuffer, 0);
  glBindTexture(GL_TEXTURE_2D, ds);
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, d.data());
  EXPECT_EQ(d[36], 0x80000008u);
  EXPECT_EQ(d[0], 0x80000008u);
  EXPECT_NO_GL_ERROR();
}

// A cube face as the depth-stencil attachment (cleared and drawn into, the
// other faces kept), and a 1D depth-stencil texture sampled as intensity.
TEST_F(DepthStencilTextureTest, CubeFaceAndOneDimensionalTexture) {
  const std::vector<GLuint> ramp = Ramp();
  std::vector<GLuint> face(64, 0x12345678u);
  const GLuint cube = texture(GL_TEXTURE_CUBE_MAP);
  for (int i = 0; i < 6; ++i)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + i, 0, kDepth24Stencil8, 8, 8, 0, kDepthStencil, kUnsignedInt24_8,
                 face.data());
  const GLuint color = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, color, 0);
  f.framebufferTexture2D(kFramebuffer, kDepthStencilAttachment, GL_TEXTURE_CUBE_MAP_POSITIVE_Y, cube, 0);
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  glViewport(0, 0, 8, 8);
  glClearDepth(0.25);
  glClearStencil(9);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glDepthFunc(GL_ALWAYS);
  glStencilFunc(GL_ALWAYS, 0x42, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glRectf(-1, -1, 0, 0);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDepthFunc(GL_LESS);
  f.bindFramebuffer(kFramebuffer, 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
  std::vector<GLuint> out(64);
  glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, kDepthStencil, kUnsignedInt24_8, out.data());
  EXPECT_EQ(out[0], 0x80000042u);
  EXPECT_EQ(out[63], 0x40000009u);
  EXPECT_EQ(Checksum(out.data(), out.size() * 4), 2594056517u);
  glGetTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, kDepthStencil, kUnsignedInt24_8, out.data());
  EXPECT_EQ(out, face);

  texture(GL_TEXTURE_1D);
  glTexImage1D(GL_TEXTURE_1D, 0, kDepthStencil, 16, 0, kDepthStencil, kUnsignedInt24_8, ramp.data());
  glTexParameteri(GL_TEXTURE_1D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_1D);
  glViewport(0, 0, 40, 8);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glTexCoord1f(0);
  glVertex2f(-1, -1);
  glTexCoord1f(1);
  glVertex2f(1, -1);
  glTexCoord1f(1);
  glVertex2f(1, 1);
  glTexCoord1f(0);
  glVertex2f(-1, 1);
  glEnd();
  glDisable(GL_TEXTURE_1D);
  std::vector<GLubyte> rgba(40 * 8 * 4);
  glReadPixels(0, 0, 40, 8, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_EQ(rgba[39 * 4 + 3], 178);  // intensity: the depth in alpha too
  EXPECT_EQ(Checksum(rgba.data(), rgba.size()), 2682597989u);
  EXPECT_NO_GL_ERROR();
}

// A depth-tested, stencilled triangle into a depth-stencil texture, read
// back, then the texture sampled in the window as luminance and compared.
TEST_F(DepthStencilTextureTest, RenderIntoThenSample) {
  const GLuint ds = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, kDepth24Stencil8, 16, 16, 0, kDepthStencil, kUnsignedInt24_8, nullptr);
  const GLuint color = texture(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, color, 0);
  f.framebufferTexture2D(kFramebuffer, kDepthStencilAttachment, GL_TEXTURE_2D, ds, 0);
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  glViewport(0, 0, 16, 16);
  glClearColor(0, 0, 0, 1);
  glClearDepth(1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 5, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColor3f(1, 0, 0);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, -0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(-1, 1, 0.25f);
  glEnd();
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glColor3f(0, 1, 0);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_DEPTH_TEST);
  std::vector<GLuint> read(256), got(256);
  glReadPixels(0, 0, 16, 16, kDepthStencil, kUnsignedInt24_8, read.data());
  std::vector<GLubyte> rgba(16 * 16 * 4);
  glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_NO_GL_ERROR();
  f.bindFramebuffer(kFramebuffer, 0);
  glBindTexture(GL_TEXTURE_2D, ds);
  glGetTexImage(GL_TEXTURE_2D, 0, kDepthStencil, kUnsignedInt24_8, got.data());
  EXPECT_EQ(got, read);
  // Mesa's values on the diagonal (the triangle's stencil 5, the rectangle's depth 0.5).
  const GLuint diagonal[4] = {0x47000005, 0x55000005, 0x63000005, 0x71000005};
  for (int i = 0; i < 4; ++i) EXPECT_EQ(got[i * 17], diagonal[i]) << i;
  EXPECT_EQ(got[15 * 17], 0x80000000u);
  int stencilled = 0;
  for (GLuint v : got) stencilled += (v & 0xff) == 5;
  EXPECT_EQ(stencilled, 120);
  EXPECT_EQ(Checksum(rgba.data(), rgba.size()), 3611155861u);

  // Sampled: the depth as luminance, then compared (ARB_shadow) as alpha.
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  auto quad = [] {
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, 0.5f);
    glVertex2f(-1, -1);
    glTexCoord3f(1, 0, 0.5f);
    glVertex2f(1, -1);
    glTexCoord3f(1, 1, 0.5f);
    glVertex2f(1, 1);
    glTexCoord3f(0, 1, 0.5f);
    glVertex2f(-1, 1);
    glEnd();
  };
  quad();
  glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_EQ(rgba[0], 71);
  EXPECT_EQ(rgba[(15 * 16 + 15) * 4], 128);
  EXPECT_EQ(Checksum(rgba.data(), rgba.size()), 4015506518u);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LESS);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glClear(GL_COLOR_BUFFER_BIT);
  quad();
  glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_EQ(Checksum(rgba.data(), rgba.size()), 762932888u);
  glDisable(GL_TEXTURE_2D);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
