// Framebuffer objects are rasterized with y up (MESA_FACTS.md "Framebuffer
// objects"): Mesa flips y for window-system buffers only, so the depth and
// float colour values llvmpipe interpolates into an object, the facing of
// its triangles, feedback coordinates and the point sprite origin are those
// of GL's own rows. The expected hashes are FNV-1a of what Mesa 22.3.6's
// llvmpipe gives (probed: this file builds against Mesa too).
#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

constexpr GLenum kFramebuffer = 0x8D40, kRenderbuffer = 0x8D41;
constexpr GLenum kColor0 = 0x8CE0, kDepthAttachment = 0x8D00, kComplete = 0x8CD5;
constexpr GLenum kRGBA32F = 0x8814;
constexpr int kN = 64;

uint32_t fnv(const void* data, size_t n) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  uint32_t h = 2166136261u;
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 16777619u;
  }
  return h;
}

template <typename F>
void load(F*& f, const char* name) {
  f = reinterpret_cast<F*>(OSMesaGetProcAddress(name));
}

class FramebufferOrientationTest : public GLTest {
 protected:
  void SetUp() override {
    GLTest::SetUp();
    load(genFramebuffers_, "glGenFramebuffers");
    load(deleteFramebuffers_, "glDeleteFramebuffers");
    load(bindFramebuffer_, "glBindFramebuffer");
    load(checkFramebufferStatus_, "glCheckFramebufferStatus");
    load(framebufferRenderbuffer_, "glFramebufferRenderbuffer");
    load(genRenderbuffers_, "glGenRenderbuffers");
    load(deleteRenderbuffers_, "glDeleteRenderbuffers");
    load(bindRenderbuffer_, "glBindRenderbuffer");
    load(renderbufferStorage_, "glRenderbufferStorage");
    ASSERT_NE(renderbufferStorage_, nullptr);
  }
  void TearDown() override {
    if (fb_) {
      bindFramebuffer_(kFramebuffer, 0);
      deleteFramebuffers_(1, &fb_);
      deleteRenderbuffers_(2, rb_);
    }
    GLTest::TearDown();
  }
  // A bound kN x kN object: colour of `format`, DEPTH_COMPONENT24.
  void bindObject(GLenum format) {
    genRenderbuffers_(2, rb_);
    bindRenderbuffer_(kRenderbuffer, rb_[0]);
    renderbufferStorage_(kRenderbuffer, format, kN, kN);
    bindRenderbuffer_(kRenderbuffer, rb_[1]);
    renderbufferStorage_(kRenderbuffer, GL_DEPTH_COMPONENT24, kN, kN);
    genFramebuffers_(1, &fb_);
    bindFramebuffer_(kFramebuffer, fb_);
    framebufferRenderbuffer_(kFramebuffer, kColor0, kRenderbuffer, rb_[0]);
    framebufferRenderbuffer_(kFramebuffer, kDepthAttachment, kRenderbuffer, rb_[1]);
    ASSERT_EQ(checkFramebufferStatus_(kFramebuffer), kComplete);
    glViewport(0, 0, kN, kN);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  std::vector<GLuint> readDepth() {
    std::vector<GLuint> z(kN * kN);
    glReadPixels(0, 0, kN, kN, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z.data());
    return z;
  }
  std::array<GLubyte, 4> readPixel(int x, int y) {
    std::array<GLubyte, 4> p{};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    return p;
  }

  void (*genFramebuffers_)(GLsizei, GLuint*) = nullptr;
  void (*deleteFramebuffers_)(GLsizei, const GLuint*) = nullptr;
  void (*bindFramebuffer_)(GLenum, GLuint) = nullptr;
  GLenum (*checkFramebufferStatus_)(GLenum) = nullptr;
  void (*framebufferRenderbuffer_)(GLenum, GLenum, GLenum, GLuint) = nullptr;
  void (*genRenderbuffers_)(GLsizei, GLuint*) = nullptr;
  void (*deleteRenderbuffers_)(GLsizei, const GLuint*) = nullptr;
  void (*bindRenderbuffer_)(GLenum, GLuint) = nullptr;
  void (*renderbufferStorage_)(GLenum, GLenum, GLsizei, GLsizei) = nullptr;
  GLuint fb_ = 0, rb_[2] = {};
};

// Two tilted, smooth, depth-tested triangles in perspective.
void drawTiltedTriangles() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLES);
  glColor4f(0.9f, 0.1f, 0.2f, 0.7f);
  glVertex3f(-1.3f, -1.1f, -2.2f);
  glColor4f(0.1f, 0.8f, 0.3f, 0.2f);
  glVertex3f(0.7f, -0.9f, -6.1f);
  glColor4f(0.3f, 0.2f, 0.9f, 1.0f);
  glVertex3f(-0.1f, 0.6f, -3.7f);
  glColor4f(0.6f, 0.7f, 0.1f, 0.5f);
  glVertex3f(1.2f, -1.3f, -2.9f);
  glColor4f(0.2f, 0.6f, 0.8f, 0.9f);
  glVertex3f(0.9f, 1.0f, -6.6f);
  glColor4f(0.7f, 0.1f, 0.7f, 0.3f);
  glVertex3f(-0.8f, -0.3f, -4.1f);
  glEnd();
  glDisable(GL_DEPTH_TEST);
}

}  // namespace

// The depth values llvmpipe interpolates into an object (y up) differ from
// the window's (y down) in the last bits on most pixels: every value here
// is Mesa's.
TEST_F(FramebufferOrientationTest, DepthOfTiltedTrianglesIsMesas) {
  bindObject(GL_RGBA8);
  drawTiltedTriangles();
  const std::vector<GLuint> z = readDepth();
  int covered = 0;
  for (GLuint v : z) covered += v != 0xffffffffu;
  EXPECT_GT(covered, 500);
  EXPECT_EQ(fnv(z.data(), z.size() * 4), 0x5a0b085fu);
  std::vector<GLubyte> rgba(kN * kN * 4);
  glReadPixels(0, 0, kN, kN, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  EXPECT_EQ(fnv(rgba.data(), rgba.size()), 0x7d34540bu);
  EXPECT_NO_GL_ERROR();
}

// Float colours keep every bit of the interpolation: Mesa's, y up.
TEST_F(FramebufferOrientationTest, FloatColourAndDepthAreMesas) {
  bindObject(kRGBA32F);
  drawTiltedTriangles();
  std::vector<GLfloat> rgba(kN * kN * 4);
  glReadPixels(0, 0, kN, kN, GL_RGBA, GL_FLOAT, rgba.data());
  EXPECT_EQ(fnv(rgba.data(), rgba.size() * 4), 0xdb3f8711u);
  const std::vector<GLuint> z = readDepth();
  EXPECT_EQ(fnv(z.data(), z.size() * 4), 0x5a0b085fu);  // the same depth as with RGBA8
  EXPECT_NO_GL_ERROR();
}

// Edges on pixel centres: GL's bottom-left rule holds in the object's rows
// too (llvmpipe's top-left rule there): the bottom row and left column of a
// rectangle of centres are in, the top row and right column out.
TEST_F(FramebufferOrientationTest, EdgesOnPixelCentres) {
  bindObject(GL_RGBA8);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kN, 0, kN, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLES);  // the rectangle of centres (4.5, 6.5) .. (10.5, 12.5) as two triangles
  glVertex2f(4.5f, 6.5f);
  glVertex2f(10.5f, 6.5f);
  glVertex2f(10.5f, 12.5f);
  glVertex2f(4.5f, 6.5f);
  glVertex2f(10.5f, 12.5f);
  glVertex2f(4.5f, 12.5f);
  glEnd();
  EXPECT_EQ(readPixel(4, 6)[0], 255);
  EXPECT_EQ(readPixel(9, 11)[0], 255);
  EXPECT_NE(readPixel(10, 8)[0], 255);
  EXPECT_NE(readPixel(6, 12)[0], 255);
  EXPECT_NE(readPixel(3, 8)[0], 255);
  EXPECT_NE(readPixel(6, 5)[0], 255);
  std::vector<GLubyte> rgba(kN * kN * 4);
  glReadPixels(0, 0, kN, kN, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  int lit = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) lit += rgba[i] == 255;
  EXPECT_EQ(lit, 36);
}

// Front stays GL's front in an object, whose rows are not flipped (Mesa flips
// its notion of front instead): culling GL_BACK keeps a counter-clockwise
// triangle, drops a clockwise one; glFrontFace(GL_CW) swaps them.
TEST_F(FramebufferOrientationTest, FacingIsGLs) {
  bindObject(GL_RGBA8);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  for (GLenum front : {GLenum(GL_CCW), GLenum(GL_CW)}) {
    SCOPED_TRACE(front == GL_CCW ? "GL_CCW" : "GL_CW");
    glClear(GL_COLOR_BUFFER_BIT);
    glFrontFace(front);
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1);  // counter-clockwise, lower left
    glVertex2f(0, -1);
    glVertex2f(-1, 0);
    glVertex2f(1, 0);  // clockwise, upper right
    glVertex2f(0, 1);
    glVertex2f(1, 1);
    glEnd();
    EXPECT_EQ(readPixel(8, 8)[0], front == GL_CCW ? 255 : 26);
    EXPECT_EQ(readPixel(56, 56)[0], front == GL_CCW ? 26 : 255);
  }
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  EXPECT_NO_GL_ERROR();
}

// GL_FEEDBACK with an object bound gives GL's window y (st_cb_feedback.c
// flips back only for a window-system buffer).
TEST_F(FramebufferOrientationTest, FeedbackYIsGLs) {
  bindObject(GL_RGBA8);
  GLfloat buffer[16] = {};
  glFeedbackBuffer(16, GL_2D, buffer);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glVertex2f(-0.5f, -0.75f);  // window (16, 8)
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 3);
  EXPECT_EQ(buffer[0], static_cast<GLfloat>(GL_POINT_TOKEN));
  EXPECT_EQ(buffer[1], 16.0f);
  EXPECT_EQ(buffer[2], 8.0f);
}

// GL_POINT_SPRITE_COORD_ORIGIN is window-relative in an object too: with
// GL_UPPER_LEFT, t = 0 at the sprite's top, GL_LOWER_LEFT at its bottom.
TEST_F(FramebufferOrientationTest, SpriteOriginIsGLs) {
  bindObject(GL_RGBA8);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const GLubyte texels[8] = {255, 0, 0, 255, 0, 255, 0, 255};  // row t = 0 red, row t = 1 green
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPointSize(8);
  for (GLint origin : {GL_UPPER_LEFT, GL_LOWER_LEFT}) {
    SCOPED_TRACE(origin == GL_UPPER_LEFT ? "GL_UPPER_LEFT" : "GL_LOWER_LEFT");
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, origin);
    glBegin(GL_POINTS);
    glVertex2f(0, 0);  // window (32, 32): pixels 28..35
    glEnd();
    const std::array<GLubyte, 4> top = readPixel(32, 34), bottom = readPixel(32, 29);
    EXPECT_EQ(top[0], origin == GL_UPPER_LEFT ? 255 : 0);
    EXPECT_EQ(top[1], origin == GL_UPPER_LEFT ? 0 : 255);
    EXPECT_EQ(bottom[0], origin == GL_UPPER_LEFT ? 0 : 255);
    EXPECT_EQ(bottom[1], origin == GL_UPPER_LEFT ? 255 : 0);
  }
  glDisable(GL_POINT_SPRITE);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
  EXPECT_NO_GL_ERROR();
}
