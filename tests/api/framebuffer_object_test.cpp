// Framebuffer objects (EXT/ARB_framebuffer_object, EXT_framebuffer_blit):
// the objects, their completeness, errors and queries, and drawing into their
// attachments, with the values Mesa 22.3.6's llvmpipe gives (probed;
// MESA_FACTS.md "Framebuffer objects"). The commands are fetched with
// OSMesaGetProcAddress, so the test builds on both implementations' headers.
#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

constexpr GLenum kFramebuffer = 0x8D40, kReadFramebuffer = 0x8CA8, kDrawFramebuffer = 0x8CA9;
constexpr GLenum kRenderbuffer = 0x8D41;
constexpr GLenum kColor0 = 0x8CE0, kDepthAttachment = 0x8D00, kStencilAttachment = 0x8D20;
constexpr GLenum kComplete = 0x8CD5, kIncompleteAttachment = 0x8CD6, kMissingAttachment = 0x8CD7,
                 kUnsupported = 0x8CDD;
constexpr GLenum kInvalidFramebufferOperation = 0x0506;
constexpr GLenum kDepth24Stencil8 = 0x88F0, kStencilIndex8 = 0x8D48;
constexpr GLenum kObjectType = 0x8CD0, kObjectName = 0x8CD1, kTextureLevel = 0x8CD2;

struct Fbo {
  void (*genFramebuffers)(GLsizei, GLuint*);
  void (*deleteFramebuffers)(GLsizei, const GLuint*);
  GLboolean (*isFramebuffer)(GLuint);
  void (*bindFramebuffer)(GLenum, GLuint);
  void (*bindFramebufferEXT)(GLenum, GLuint);
  GLenum (*checkFramebufferStatus)(GLenum);
  GLenum (*checkFramebufferStatusEXT)(GLenum);
  void (*framebufferTexture2D)(GLenum, GLenum, GLenum, GLuint, GLint);
  void (*framebufferTexture3D)(GLenum, GLenum, GLenum, GLuint, GLint, GLint);
  void (*framebufferRenderbuffer)(GLenum, GLenum, GLenum, GLuint);
  void (*getFramebufferAttachmentParameteriv)(GLenum, GLenum, GLenum, GLint*);
  void (*genRenderbuffers)(GLsizei, GLuint*);
  void (*deleteRenderbuffers)(GLsizei, const GLuint*);
  GLboolean (*isRenderbuffer)(GLuint);
  void (*bindRenderbuffer)(GLenum, GLuint);
  void (*renderbufferStorage)(GLenum, GLenum, GLsizei, GLsizei);
  void (*renderbufferStorageMultisample)(GLenum, GLsizei, GLenum, GLsizei, GLsizei);
  void (*getRenderbufferParameteriv)(GLenum, GLenum, GLint*);
  void (*blitFramebuffer)(GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLint, GLbitfield, GLenum);
  void (*drawBuffers)(GLsizei, const GLenum*);
  void (*generateMipmapEXT)(GLenum);
};

template <typename F>
void load(F*& f, const char* name) {
  f = reinterpret_cast<F*>(OSMesaGetProcAddress(name));
}

class FramebufferObjectTest : public GLTest {
 protected:
  void SetUp() override {
    GLTest::SetUp();
    load(f.genFramebuffers, "glGenFramebuffers");
    load(f.deleteFramebuffers, "glDeleteFramebuffers");
    load(f.isFramebuffer, "glIsFramebuffer");
    load(f.bindFramebuffer, "glBindFramebuffer");
    load(f.bindFramebufferEXT, "glBindFramebufferEXT");
    load(f.checkFramebufferStatus, "glCheckFramebufferStatus");
    load(f.checkFramebufferStatusEXT, "glCheckFramebufferStatusEXT");
    load(f.framebufferTexture2D, "glFramebufferTexture2D");
    load(f.framebufferTexture3D, "glFramebufferTexture3D");
    load(f.framebufferRenderbuffer, "glFramebufferRenderbuffer");
    load(f.getFramebufferAttachmentParameteriv, "glGetFramebufferAttachmentParameteriv");
    load(f.genRenderbuffers, "glGenRenderbuffers");
    load(f.deleteRenderbuffers, "glDeleteRenderbuffers");
    load(f.isRenderbuffer, "glIsRenderbuffer");
    load(f.bindRenderbuffer, "glBindRenderbuffer");
    load(f.renderbufferStorage, "glRenderbufferStorage");
    load(f.renderbufferStorageMultisample, "glRenderbufferStorageMultisample");
    load(f.getRenderbufferParameteriv, "glGetRenderbufferParameteriv");
    load(f.blitFramebuffer, "glBlitFramebuffer");
    load(f.drawBuffers, "glDrawBuffers");
    load(f.generateMipmapEXT, "glGenerateMipmapEXT");
    ASSERT_NE(f.genFramebuffers, nullptr);
    ASSERT_NE(f.bindFramebufferEXT, nullptr);
    ASSERT_NE(f.checkFramebufferStatusEXT, nullptr);
    ASSERT_NE(f.blitFramebuffer, nullptr);
    ASSERT_NE(f.renderbufferStorageMultisample, nullptr);
    ASSERT_NE(f.drawBuffers, nullptr);
    ASSERT_NE(f.generateMipmapEXT, nullptr);
  }

  GLuint renderbuffer(GLenum format, int w, int h) {
    GLuint rb = 0;
    f.genRenderbuffers(1, &rb);
    f.bindRenderbuffer(kRenderbuffer, rb);
    f.renderbufferStorage(kRenderbuffer, format, w, h);
    return rb;
  }
  GLuint texture2D(GLenum internal, GLenum format, GLenum type, int w, int h) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, w, h, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
  }
  // A bound framebuffer with an RGBA8 renderbuffer of w x h at colour 0.
  GLuint colorFramebuffer(int w, int h, GLuint* rb = nullptr) {
    GLuint fb = 0;
    f.genFramebuffers(1, &fb);
    const GLuint c = renderbuffer(GL_RGBA8, w, h);
    f.bindFramebuffer(kFramebuffer, fb);
    f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, c);
    if (rb) *rb = c;
    return fb;
  }
  GLint rbParam(GLenum pname) {
    GLint v = -7;
    f.getRenderbufferParameteriv(kRenderbuffer, pname, &v);
    return v;
  }
  GLint attachmentParam(GLenum point, GLenum pname) {
    GLint v = -7;
    f.getFramebufferAttachmentParameteriv(kFramebuffer, point, pname, &v);
    return v;
  }
  std::array<GLubyte, 4> readPixel(int x, int y) {
    std::array<GLubyte, 4> p{};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    return p;
  }

  Fbo f{};
};

TEST_F(FramebufferObjectTest, LimitsAndInitialBindings) {
  EXPECT_EQ(GetInt(0x84E8), 16384);                              // GL_MAX_RENDERBUFFER_SIZE
  EXPECT_EQ(GetInt(0x8CDF), 8);                                  // GL_MAX_COLOR_ATTACHMENTS
  EXPECT_EQ(GetInt(0x8824), 8);                                  // GL_MAX_DRAW_BUFFERS
  EXPECT_EQ(GetInt(0x8CA6), 0);                                  // GL_FRAMEBUFFER_BINDING
  EXPECT_EQ(GetInt(0x8CAA), 0);                                  // GL_READ_FRAMEBUFFER_BINDING
  EXPECT_EQ(GetInt(0x8CA7), 0);                                  // GL_RENDERBUFFER_BINDING
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);  // the window's
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferObjectTest, NamesAndBinding) {
  GLuint fb = 0, rb = 0;
  f.genFramebuffers(1, &fb);
  f.genRenderbuffers(1, &rb);
  EXPECT_NE(fb, 0u);
  EXPECT_EQ(f.isFramebuffer(fb), GL_FALSE);  // generated, not bound yet
  EXPECT_EQ(f.isRenderbuffer(rb), GL_FALSE);
  f.bindFramebuffer(kFramebuffer, fb);
  f.bindRenderbuffer(kRenderbuffer, rb);
  EXPECT_EQ(f.isFramebuffer(fb), GL_TRUE);
  EXPECT_EQ(f.isRenderbuffer(rb), GL_TRUE);
  EXPECT_EQ(GetInt(0x8CA6), static_cast<GLint>(fb));
  EXPECT_EQ(GetInt(0x8CAA), static_cast<GLint>(fb));
  EXPECT_EQ(GetInt(0x8CA7), static_cast<GLint>(rb));
  // The object's own draw and read buffers; the window's come back.
  EXPECT_EQ(GetInt(GL_DRAW_BUFFER), static_cast<GLint>(kColor0));
  EXPECT_EQ(GetInt(GL_READ_BUFFER), static_cast<GLint>(kColor0));
  EXPECT_EQ(GetInt(0x8826), GL_NONE);  // GL_DRAW_BUFFER1
  f.bindFramebuffer(kFramebuffer, 0);
  EXPECT_EQ(GetInt(GL_DRAW_BUFFER), GL_FRONT);
  // Mesa binds names never generated, with the EXT and the ARB command.
  f.bindFramebufferEXT(kFramebuffer, 4242);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(f.isFramebuffer(4242), GL_TRUE);
  // Separate draw and read bindings, also through the EXT name.
  f.bindFramebufferEXT(kDrawFramebuffer, fb);
  EXPECT_EQ(GetInt(0x8CA6), static_cast<GLint>(fb));
  EXPECT_EQ(GetInt(0x8CAA), 4242);
  f.bindFramebuffer(kReadFramebuffer, 0);
  EXPECT_EQ(GetInt(0x8CAA), 0);
  EXPECT_NO_GL_ERROR();
  f.bindFramebuffer(GL_TEXTURE_2D, fb);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.bindRenderbuffer(GL_TEXTURE_2D, rb);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.genFramebuffers(-1, &fb);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  f.deleteFramebuffers(-1, &fb);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  f.genRenderbuffers(-1, &rb);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  f.bindFramebuffer(kFramebuffer, 0);  // an incomplete one would refuse the glBegin
  glBegin(GL_POINTS);
  f.bindFramebuffer(kFramebuffer, fb);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.bindFramebuffer(kFramebuffer, fb);
  // Deleting the bound framebuffer binds 0.
  f.deleteFramebuffers(1, &fb);
  EXPECT_EQ(GetInt(0x8CA6), 0);
  EXPECT_EQ(f.isFramebuffer(fb), GL_FALSE);
  f.deleteRenderbuffers(1, &rb);
  EXPECT_EQ(GetInt(0x8CA7), 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferObjectTest, RenderbufferStorageAndParameters) {
  struct Case {
    GLenum format;
    GLint r, g, b, a, d, s;
  };
  const Case cases[] = {
      {GL_RGBA, 8, 8, 8, 8, 0, 0},
      {GL_RGB, 8, 8, 8, 0, 0, 0},
      {GL_RGBA8, 8, 8, 8, 8, 0, 0},
      {GL_RGB8, 8, 8, 8, 0, 0, 0},
      {GL_RGBA4, 4, 4, 4, 4, 0, 0},
      {GL_RGB5_A1, 5, 5, 5, 1, 0, 0},
      {GL_DEPTH_COMPONENT, 0, 0, 0, 0, 24, 0},
      {GL_DEPTH_COMPONENT16, 0, 0, 0, 0, 16, 0},
      {GL_DEPTH_COMPONENT24, 0, 0, 0, 0, 24, 0},
      {GL_DEPTH_COMPONENT32, 0, 0, 0, 0, 32, 0},
      {kStencilIndex8, 0, 0, 0, 0, 0, 8},
      {kDepth24Stencil8, 0, 0, 0, 0, 24, 8},
  };
  GLuint rb = 0;
  f.genRenderbuffers(1, &rb);
  f.bindRenderbuffer(kRenderbuffer, rb);
  EXPECT_EQ(rbParam(0x8D44), GL_RGBA);  // the initial internal format
  EXPECT_EQ(rbParam(0x8D42), 0);
  for (const Case& c : cases) {
    f.renderbufferStorage(kRenderbuffer, c.format, 16, 8);
    EXPECT_NO_GL_ERROR() << std::hex << c.format;
    EXPECT_EQ(rbParam(0x8D42), 16);
    EXPECT_EQ(rbParam(0x8D43), 8);
    EXPECT_EQ(rbParam(0x8D44), static_cast<GLint>(c.format));
    EXPECT_EQ(rbParam(0x8D50), c.r) << std::hex << c.format;
    EXPECT_EQ(rbParam(0x8D51), c.g);
    EXPECT_EQ(rbParam(0x8D52), c.b);
    EXPECT_EQ(rbParam(0x8D53), c.a);
    EXPECT_EQ(rbParam(0x8D54), c.d);
    EXPECT_EQ(rbParam(0x8D55), c.s);
    EXPECT_EQ(rbParam(0x8CAB), 0);  // samples
  }
  f.renderbufferStorage(kRenderbuffer, 0x1234, 4, 4);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.renderbufferStorage(GL_TEXTURE_2D, GL_RGBA8, 4, 4);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.renderbufferStorage(kRenderbuffer, GL_RGBA8, -1, 4);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  f.renderbufferStorage(kRenderbuffer, GL_RGBA8, 16385, 4);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  // Huge but within the maximum: no error (llvmpipe allocates lazily), no crash.
  f.renderbufferStorage(kRenderbuffer, GL_RGBA8, 16384, 16384);
  const GLenum huge = glGetError();
  EXPECT_TRUE(huge == GL_NO_ERROR || huge == GL_OUT_OF_MEMORY);
  f.renderbufferStorage(kRenderbuffer, GL_RGBA8, 4, 4);
  // Multisample: 0 samples is the plain storage; llvmpipe has 4, and rounds up to them.
  f.renderbufferStorageMultisample(kRenderbuffer, 0, GL_RGBA8, 4, 4);
  EXPECT_EQ(rbParam(0x8CAB), 0);
  f.renderbufferStorageMultisample(kRenderbuffer, 2, GL_RGBA8, 4, 4);
  EXPECT_EQ(rbParam(0x8CAB), 4);
  f.renderbufferStorageMultisample(kRenderbuffer, 64, GL_RGBA8, 4, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.getRenderbufferParameteriv(kRenderbuffer, 0x1234, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  // Renderbuffer 0.
  f.bindRenderbuffer(kRenderbuffer, 0);
  f.renderbufferStorage(kRenderbuffer, GL_RGBA8, 4, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLint v = -7;
  f.getRenderbufferParameteriv(kRenderbuffer, 0x8D42, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

TEST_F(FramebufferObjectTest, CompletenessStatuses) {
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kMissingAttachment);
  EXPECT_EQ(GetInt(GL_RED_BITS), 0);
  const GLuint color = renderbuffer(GL_RGBA8, 16, 16);
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, color);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_EQ(GetInt(GL_RED_BITS), 8);
  EXPECT_EQ(GetInt(GL_DEPTH_BITS), 0);
  // Attachments of other sizes and formats: complete (ARB), for the EXT query too.
  const GLuint depth = renderbuffer(GL_DEPTH_COMPONENT24, 8, 16);
  f.framebufferRenderbuffer(kFramebuffer, kDepthAttachment, kRenderbuffer, depth);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_EQ(f.checkFramebufferStatusEXT(kFramebuffer), kComplete);
  EXPECT_EQ(GetInt(GL_DEPTH_BITS), 24);
  // Separate depth and stencil buffers: llvmpipe's state tracker refuses them.
  const GLuint stencil = renderbuffer(kStencilIndex8, 16, 16);
  f.framebufferRenderbuffer(kFramebuffer, kStencilAttachment, kRenderbuffer, stencil);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kUnsupported);
  f.framebufferRenderbuffer(kFramebuffer, kDepthAttachment, kRenderbuffer, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);  // colour + stencil alone
  f.framebufferRenderbuffer(kFramebuffer, kStencilAttachment, kRenderbuffer, 0);
  // A depth buffer at a colour attachment, a zero-size one, one without storage.
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, depth);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  f.bindRenderbuffer(kRenderbuffer, color);
  f.renderbufferStorage(kRenderbuffer, GL_RGBA8, 0, 0);
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, color);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  // A depth-only object is complete, whatever its draw buffer.
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, 0);
  f.framebufferRenderbuffer(kFramebuffer, kDepthAttachment, kRenderbuffer, depth);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  // Texture levels: an undefined level is an incomplete attachment; a colour
  // texture is one at the depth attachment.
  const GLuint tex = texture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 16, 16);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 1);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  f.framebufferTexture2D(kFramebuffer, kDepthAttachment, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(f.checkFramebufferStatus(kFramebuffer), kIncompleteAttachment);
  f.checkFramebufferStatus(GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

TEST_F(FramebufferObjectTest, AttachmentErrors) {
  const GLuint rb = renderbuffer(GL_RGBA8, 4, 4);
  const GLuint tex = texture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 4);
  // The window's framebuffer takes no attachment.
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, rb);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLint v = -7;
  f.getFramebufferAttachmentParameteriv(kFramebuffer, GL_BACK_LEFT, kObjectType, &v);
  EXPECT_EQ(v, 0x8218);  // GL_FRAMEBUFFER_DEFAULT
  f.getFramebufferAttachmentParameteriv(kFramebuffer, kColor0, kObjectType, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLuint fb = 0, unbound = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  f.genRenderbuffers(1, &unbound);
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, unbound);  // never bound
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.framebufferRenderbuffer(kFramebuffer, kColor0, kRenderbuffer, 12345);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.framebufferRenderbuffer(kFramebuffer, kColor0 + 8, kRenderbuffer, rb);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.framebufferRenderbuffer(kFramebuffer, kColor0, GL_TEXTURE_2D, rb);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_3D, tex, 0);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_CUBE_MAP_POSITIVE_X, tex, 0);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.framebufferTexture2D(kFramebuffer, kColor0, 0x1234, tex, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, 999, 0);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 15);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  f.framebufferTexture2D(kFramebuffer, 0x1234, GL_TEXTURE_2D, tex, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  // Queries of what is attached.
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 0);
  f.framebufferRenderbuffer(kFramebuffer, kDepthAttachment, kRenderbuffer,
                            renderbuffer(GL_DEPTH_COMPONENT24, 4, 4));
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(attachmentParam(kColor0, kObjectType), GL_TEXTURE);
  EXPECT_EQ(attachmentParam(kColor0, kObjectName), static_cast<GLint>(tex));
  EXPECT_EQ(attachmentParam(kColor0, kTextureLevel), 0);
  EXPECT_EQ(attachmentParam(kColor0, 0x8CD3), 0);  // cube map face
  EXPECT_EQ(attachmentParam(kColor0, 0x8212), 8);  // red size
  EXPECT_EQ(attachmentParam(kDepthAttachment, kObjectType), static_cast<GLint>(kRenderbuffer));
  EXPECT_EQ(attachmentParam(kDepthAttachment, 0x8216), 24);  // depth size
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(attachmentParam(kColor0 + 1, kObjectType), GL_NONE);
  EXPECT_EQ(attachmentParam(kColor0 + 1, kObjectName), 0);
  EXPECT_NO_GL_ERROR();
  attachmentParam(kColor0 + 1, kTextureLevel);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  attachmentParam(kDepthAttachment, kTextureLevel);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  // glDrawBuffer / glReadBuffer with an object bound.
  glDrawBuffer(GL_BACK);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawBuffer(kColor0 + 8);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawBuffer(0x1234);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glReadBuffer(GL_FRONT);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawBuffer(kColor0 + 3);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_DRAW_BUFFER), static_cast<GLint>(kColor0 + 3));
  // Deleting attached objects detaches them from the bound framebuffer.
  glDeleteTextures(1, &tex);
  EXPECT_EQ(attachmentParam(kColor0, kObjectType), GL_NONE);
  GLuint depth = static_cast<GLuint>(attachmentParam(kDepthAttachment, kObjectName));
  f.deleteRenderbuffers(1, &depth);
  EXPECT_EQ(attachmentParam(kDepthAttachment, kObjectType), GL_NONE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferObjectTest, IncompleteFramebufferDrawsNothing) {
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  f.bindFramebuffer(kFramebuffer, fb);
  const GLuint tex = texture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 8, 8);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 1);  // undefined level
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_GL_ERROR(kInvalidFramebufferOperation);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(1, 0);
  glVertex2f(0, 1);
  glEnd();
  EXPECT_EQ(DrainErrors(), kInvalidFramebufferOperation);
  GLubyte p[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_GL_ERROR(kInvalidFramebufferOperation);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 4, 0);
  EXPECT_GL_ERROR(kInvalidFramebufferOperation);
  // The window was not touched.
  f.bindFramebuffer(kFramebuffer, 0);
  EXPECT_EQ(pixels()[0], 0xA5);
}

TEST_F(FramebufferObjectTest, DrawIntoRenderbuffers) {
  GLuint fb = colorFramebuffer(16, 16);
  f.framebufferRenderbuffer(kFramebuffer, kDepthAttachment, kRenderbuffer,
                            renderbuffer(GL_DEPTH_COMPONENT24, 16, 16));
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  // The viewport stays the user's: the window's size.
  EXPECT_EQ(GetInt(GL_VIEWPORT + 0), 0);
  glViewport(0, 0, 16, 16);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  EXPECT_EQ(readPixel(0, 0), (std::array<GLubyte, 4>{64, 128, 191, 255}));
  glEnable(GL_DEPTH_TEST);
  glColor3f(1, 0, 0);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, 0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(-1, 1, 0.5f);
  glEnd();
  // y is up: the lower left is the triangle's, the upper right the clear colour's.
  EXPECT_EQ(readPixel(0, 0), (std::array<GLubyte, 4>{255, 0, 0, 255}));
  EXPECT_EQ(readPixel(15, 15), (std::array<GLubyte, 4>{64, 128, 191, 255}));
  GLuint z = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
  EXPECT_EQ(z, 0xbfffffbfu);
  // The window is untouched by all this.
  f.bindFramebuffer(kFramebuffer, 0);
  EXPECT_EQ(pixels()[0], 0xA5);
  f.deleteFramebuffers(1, &fb);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferObjectTest, RenderToTextureThenSample) {
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  const GLuint tex = texture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 8, 8);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, tex, 0);
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  glViewport(0, 0, 8, 8);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 0);
  glRectf(-1, -1, 0, 0);  // the lower left quarter
  GLubyte texels[8 * 8 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  EXPECT_EQ(texels[0], 255);
  EXPECT_EQ(texels[2], 0);
  EXPECT_EQ(texels[(7 * 8 + 7) * 4 + 2], 255);
  // Sampled in the window: the new texels.
  f.bindFramebuffer(kFramebuffer, 0);
  glViewport(0, 0, kWidth, kHeight);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
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
  EXPECT_EQ(readPixel(2, 2), (std::array<GLubyte, 4>{255, 255, 0, 255}));
  EXPECT_EQ(readPixel(60, 60), (std::array<GLubyte, 4>{0, 0, 255, 255}));
  // glGenerateMipmapEXT is there for it.
  f.generateMipmapEXT(GL_TEXTURE_2D);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferObjectTest, DepthTextureShadowMap) {
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  const GLuint depth = texture2D(GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, 8, 8);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kDepthAttachment, GL_TEXTURE_2D, depth, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  glViewport(0, 0, 8, 8);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glBegin(GL_TRIANGLES);  // the lower left half at depth 0.5
  glVertex3f(-1, -1, 0);
  glVertex3f(1, -1, 0);
  glVertex3f(-1, 1, 0);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  GLuint z[64];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
  // z 0.5: the 24-bit 0x800000, packed as Mesa packs depth (truncated).
  EXPECT_EQ(z[0], 0x800000ffu);
  EXPECT_EQ(z[63], 0xffffffffu);  // cleared to 1
  // Compared in the window: r 0.75 passes LEQUAL only where the depth is 1.
  f.bindFramebuffer(kFramebuffer, 0);
  glViewport(0, 0, kWidth, kHeight);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.75f);
  glVertex2f(-1, -1);
  glTexCoord3f(1, 0, 0.75f);
  glVertex2f(1, -1);
  glTexCoord3f(1, 1, 0.75f);
  glVertex2f(1, 1);
  glTexCoord3f(0, 1, 0.75f);
  glVertex2f(-1, 1);
  glEnd();
  EXPECT_EQ(readPixel(2, 2)[0], 0);
  EXPECT_EQ(readPixel(60, 60)[0], 255);
}

TEST_F(FramebufferObjectTest, PackedDepthStencilRenderbuffer) {
  GLuint color = 0;
  colorFramebuffer(16, 16, &color);
  f.bindRenderbuffer(kRenderbuffer, color);
  f.renderbufferStorage(kRenderbuffer, GL_RGB8, 16, 16);
  const GLuint ds = renderbuffer(kDepth24Stencil8, 16, 16);
  f.framebufferRenderbuffer(kFramebuffer, kDepthAttachment, kRenderbuffer, ds);
  f.framebufferRenderbuffer(kFramebuffer, kStencilAttachment, kRenderbuffer, ds);
  ASSERT_EQ(f.checkFramebufferStatus(kFramebuffer), kComplete);
  EXPECT_EQ(GetInt(GL_STENCIL_BITS), 8);
  EXPECT_EQ(GetInt(GL_ALPHA_BITS), 0);
  glViewport(0, 0, 16, 16);
  glClearStencil(0);
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColor3f(1, 1, 1);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  glStencilFunc(GL_NOTEQUAL, 1, 0xff);
  glColor3f(0, 0, 1);
  glRectf(-1, -1, 1, 1);
  glDisable(GL_STENCIL_TEST);
  EXPECT_EQ(readPixel(0, 0), (std::array<GLubyte, 4>{0, 0, 255, 255}));  // no alpha: 1
  EXPECT_EQ(readPixel(8, 8), (std::array<GLubyte, 4>{255, 255, 255, 255}));
  GLubyte s = 7;
  glReadPixels(8, 8, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  EXPECT_EQ(s, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(FramebufferObjectTest, DrawBuffersBroadcastTheColour) {
  GLuint fb = 0;
  f.genFramebuffers(1, &fb);
  const GLuint a = texture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 8, 8);
  const GLuint b = texture2D(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 8, 8);
  f.bindFramebuffer(kFramebuffer, fb);
  f.framebufferTexture2D(kFramebuffer, kColor0, GL_TEXTURE_2D, a, 0);
  f.framebufferTexture2D(kFramebuffer, kColor0 + 1, GL_TEXTURE_2D, b, 0);
  const GLenum bufs[2] = {kColor0, kColor0 + 1};
  f.drawBuffers(2, bufs);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(0x8826), static_cast<GLint>(kColor0 + 1));  // GL_DRAW_BUFFER1
  glViewport(0, 0, 8, 8);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 0);
  glRectf(-1, -1, 0, 0);
  glReadBuffer(kColor0 + 1);
  EXPECT_EQ(readPixel(0, 0), (std::array<GLubyte, 4>{255, 255, 0, 255}));
  EXPECT_EQ(readPixel(7, 7), (std::array<GLubyte, 4>{0, 0, 255, 255}));
  glReadBuffer(kColor0);
  EXPECT_EQ(readPixel(0, 0), (std::array<GLubyte, 4>{255, 255, 0, 255}));
  const GLenum twice[2] = {kColor0, kColor0};
  f.drawBuffers(2, twice);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  const GLenum back[1] = {GL_BACK};
  f.drawBuffers(1, back);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.drawBuffers(9, bufs);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(FramebufferObjectTest, BlitNearestScaledAndErrors) {
  GLuint fb = colorFramebuffer(4, 4);
  glViewport(0, 0, 4, 4);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(0, 1, 0);
  glRectf(-1, -1, 0, 0);  // 2x2 green at the lower left
  f.bindFramebuffer(kReadFramebuffer, fb);
  f.bindFramebuffer(kDrawFramebuffer, 0);
  f.blitFramebuffer(0, 0, 4, 4, 0, 0, 32, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  EXPECT_NO_GL_ERROR();
  f.blitFramebuffer(0, 0, 4, 4, 32, 0, 64, 32, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  f.blitFramebuffer(0, 0, 4, 4, 32, 0, 64, 32, GL_COLOR_BUFFER_BIT, 0x1234);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  f.blitFramebuffer(0, 0, 4, 4, 32, 0, 64, 32, 0x80000000u, GL_NEAREST);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  // Flipped in x into the window's upper half.
  f.blitFramebuffer(4, 0, 0, 4, 0, 32, 32, 64, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  f.bindFramebuffer(kFramebuffer, 0);
  EXPECT_EQ(readPixel(5, 5), (std::array<GLubyte, 4>{0, 255, 0, 255}));
  EXPECT_EQ(readPixel(20, 5), (std::array<GLubyte, 4>{255, 0, 0, 255}));
  EXPECT_EQ(readPixel(5, 20), (std::array<GLubyte, 4>{255, 0, 0, 255}));
  EXPECT_EQ(readPixel(27, 37), (std::array<GLubyte, 4>{0, 255, 0, 255}));
  EXPECT_EQ(readPixel(5, 37), (std::array<GLubyte, 4>{255, 0, 0, 255}));
}

TEST_F(FramebufferObjectTest, ObjectsAreSharedWithSharingContexts) {
  GLuint rb = renderbuffer(GL_RGBA8, 4, 4);
  OSMesaContext other = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, ctx_);
  ASSERT_NE(other, nullptr);
  std::vector<unsigned char> buf(kWidth * kHeight * 4);
  ASSERT_EQ(OSMesaMakeCurrent(other, buf.data(), GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(f.isRenderbuffer(rb), GL_TRUE);
  OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight);
  OSMesaDestroyContext(other);
}

}  // namespace
