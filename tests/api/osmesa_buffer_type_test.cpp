// OSMesa's colour buffers of other types than GL_UNSIGNED_BYTE (16-bit unorm,
// float, 5-6-5), as Mesa 22.3.6 (llvmpipe) has them: which (format, type)
// pairs OSMesaMakeCurrent takes, what GL_*_BITS and OSMesaGetColorBuffer
// report, what a clear and a draw leave in memory and in glReadPixels
// (reference/MESA_FACTS.md, "OSMesa colour buffer types"). Passes on Mesa too.
#include <cstring>
#include <vector>

#include "api/gl_test_fixture.h"

using namespace glfx_test;

namespace {

constexpr int kW = 8, kH = 4;

// A context of `format` bound to a buffer of `type`, released at the end.
class TypedBuffer {
 public:
  TypedBuffer(GLenum format, GLenum type)
      : ctx_(OSMesaCreateContextExt(format, 24, 0, 0, NULL)), mem_(kW * kH * 16) {
    std::memset(mem_.data(), 0xA5, mem_.size());
    ok_ = ctx_ && OSMesaMakeCurrent(ctx_, mem_.data(), type, kW, kH) == GL_TRUE;
  }
  ~TypedBuffer() {
    if (!ctx_) return;
    if (OSMesaGetCurrentContext() == ctx_) OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
  }
  bool ok() const { return ok_; }
  OSMesaContext ctx() const { return ctx_; }
  const uint16_t* u16() const { return reinterpret_cast<const uint16_t*>(mem_.data()); }
  const float* f32() const { return reinterpret_cast<const float*>(mem_.data()); }
  void* data() { return mem_.data(); }

 private:
  OSMesaContext ctx_;
  std::vector<unsigned char> mem_;
  bool ok_ = false;
};

void PixelOrtho() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void Point(int x, float r, float g, float b, float a) {
  glBegin(GL_POINTS);
  glColor4f(r, g, b, a);
  glVertex2f(x + 0.5f, 0.5f);
  glEnd();
}

}  // namespace

TEST(OsmesaBufferTypeTest, MakeCurrentTakesTheTypesMesaTakes) {
  struct Case {
    GLenum format, type;
    bool accepted;
  };
  const Case cases[] = {
      {OSMESA_RGBA, GL_UNSIGNED_SHORT, true},
      {OSMESA_BGRA, GL_UNSIGNED_SHORT, true},
      {OSMESA_ARGB, GL_UNSIGNED_SHORT, true},
      {OSMESA_RGB, GL_UNSIGNED_SHORT, true},
      {OSMESA_BGR, GL_UNSIGNED_SHORT, false},
      {OSMESA_RGBA, GL_FLOAT, true},
      {OSMESA_BGRA, GL_FLOAT, true},
      {OSMESA_ARGB, GL_FLOAT, true},
      {OSMESA_RGB, GL_FLOAT, true},
      {OSMESA_BGR, GL_FLOAT, false},
      {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, true},
      {OSMESA_RGB_565, GL_UNSIGNED_BYTE, false},
      {OSMESA_RGB_565, GL_UNSIGNED_SHORT, false},
      {OSMESA_RGB_565, GL_FLOAT, false},
      {OSMESA_RGBA, GL_UNSIGNED_SHORT_5_6_5, false},
      {OSMESA_RGBA, GL_INT, false},
  };
  for (const Case& c : cases) {
    TypedBuffer b(c.format, c.type);
    EXPECT_EQ(b.ok(), c.accepted) << "format 0x" << std::hex << c.format << " type 0x" << c.type;
  }
}

TEST(OsmesaBufferTypeTest, BitsTypeAndColorBuffer) {
  struct Case {
    GLenum format, type;
    int bits[4];
  };
  const Case cases[] = {
      {OSMESA_RGBA, GL_UNSIGNED_SHORT, {16, 16, 16, 16}},
      {OSMESA_RGB, GL_UNSIGNED_SHORT, {16, 16, 16, 0}},
      {OSMESA_BGRA, GL_FLOAT, {32, 32, 32, 32}},
      {OSMESA_RGB, GL_FLOAT, {32, 32, 32, 0}},
      {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, {5, 6, 5, 0}},
  };
  for (const Case& c : cases) {
    TypedBuffer b(c.format, c.type);
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(GetInt(GL_RED_BITS), c.bits[0]);
    EXPECT_EQ(GetInt(GL_GREEN_BITS), c.bits[1]);
    EXPECT_EQ(GetInt(GL_BLUE_BITS), c.bits[2]);
    EXPECT_EQ(GetInt(GL_ALPHA_BITS), c.bits[3]);
    GLint v = 0;
    OSMesaGetIntegerv(OSMESA_TYPE, &v);
    EXPECT_EQ(v, static_cast<GLint>(c.type));
    OSMesaGetIntegerv(OSMESA_FORMAT, &v);
    EXPECT_EQ(v, static_cast<GLint>(c.format));
    GLint w = 0, h = 0, f = 0;
    void* p = nullptr;
    EXPECT_EQ(OSMesaGetColorBuffer(b.ctx(), &w, &h, &f, &p), GL_TRUE);
    EXPECT_EQ(w, kW);
    EXPECT_EQ(h, kH);
    EXPECT_EQ(f, static_cast<GLint>(c.format));  // the OSMesa format, whatever the type
    EXPECT_EQ(p, b.data());
    EXPECT_NO_GL_ERROR();
  }
}

// 16-bit buffers hold R, G, B, A in that order whatever the OSMesa format;
// a clear is rint(c * 65535), as is a fragment's colour.
TEST(OsmesaBufferTypeTest, SixteenBitClearAndDrawAreRgbaInMemory) {
  for (GLenum format : {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB}) {
    TypedBuffer b(format, GL_UNSIGNED_SHORT);
    ASSERT_TRUE(b.ok());
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    PixelOrtho();
    Point(1, 0.123456f, 0.7f, 1.0f, 0.0f);
    glFinish();
    const uint16_t* p = b.u16();
    EXPECT_EQ(p[0], 16384);
    EXPECT_EQ(p[1], 32768);
    EXPECT_EQ(p[2], 49151);
    EXPECT_EQ(p[3], 65535);
    EXPECT_EQ(p[4], 8091);   // 0.123456 * 65535 = 8090.7
    EXPECT_EQ(p[5], 45874);  // 0.7f * 65535 = 45874.499...
    EXPECT_EQ(p[6], 65535);
    EXPECT_EQ(p[7], 0);
    uint16_t us[4] = {};
    glReadPixels(1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, us);
    EXPECT_EQ(us[0], 8091);
    EXPECT_EQ(us[1], 45874);
    float fl[4] = {};
    glReadPixels(1, 0, 1, 1, GL_RGBA, GL_FLOAT, fl);
    EXPECT_FLOAT_EQ(fl[0], 8091.0f / 65535.0f);
    GLubyte ub[4] = {};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    EXPECT_EQ(ub[0], 64);
    EXPECT_EQ(ub[1], 128);
    EXPECT_EQ(ub[2], 191);
    EXPECT_EQ(ub[3], 255);
    EXPECT_NO_GL_ERROR();
  }
}

// llvmpipe blends 16-bit channels in 16-bit fixed point: t = a * b gives
// (t + (t >> 16) + 0x8000) >> 16, not the float result (30081, 42001 here).
TEST(OsmesaBufferTypeTest, SixteenBitBlendingIsFixedPoint) {
  TypedBuffer b(OSMESA_RGBA, GL_UNSIGNED_SHORT);
  ASSERT_TRUE(b.ok());
  PixelOrtho();
  Point(0, 0.2f, 0.4f, 0.6f, 0.8f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  Point(0, 0.9f, 0.3f, 0.77f, 0.37f);
  glFinish();
  const uint16_t* p = b.u16();
  EXPECT_EQ(p[0], 30080);
  EXPECT_EQ(p[1], 23789);
  EXPECT_EQ(p[2], 43443);
  EXPECT_EQ(p[3], 42002);
}

// Float buffers: clears keep values outside [0, 1]; blending is in float;
// glReadPixels clamps (the buffer is not in float mode).
TEST(OsmesaBufferTypeTest, FloatClearBlendAndRead) {
  TypedBuffer b(OSMESA_RGBA, GL_FLOAT);
  ASSERT_TRUE(b.ok());
  glClearColor(1.5f, -0.5f, 0.333f, 2.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  const float* p = b.f32();
  EXPECT_EQ(p[0], 1.5f);
  EXPECT_EQ(p[1], -0.5f);
  EXPECT_EQ(p[2], 0.333f);
  EXPECT_EQ(p[3], 2.0f);
  float fl[4] = {};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, fl);
  EXPECT_EQ(fl[0], 1.0f);
  EXPECT_EQ(fl[1], 0.0f);
  EXPECT_EQ(fl[2], 0.333f);
  EXPECT_EQ(fl[3], 1.0f);
  PixelOrtho();
  Point(1, 0.2f, 0.4f, 0.6f, 0.8f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  Point(1, 0.9f, 0.3f, 0.77f, 0.37f);
  glFinish();
  const float a = 0.37f, na = 1.0f - a;
  volatile float s = 0.9f * a, d = 0.2f * na;  // two roundings, then the sum
  EXPECT_EQ(p[4], s + d);
  uint16_t us[4] = {};
  glReadPixels(1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT, us);
  EXPECT_EQ(us[0], 30081);
  EXPECT_NO_GL_ERROR();
}

// The colour sum without lighting (GL_COLOR_SUM, GL 2.1 §3.9): the current
// secondary colour, clamped to [0, 1], is added to the clamped primary; on a
// float buffer the sum is stored unclamped (1.5), on an 8-bit one it is
// clamped at the write.
TEST(OsmesaBufferTypeTest, UnlitColourSumIsUnclampedOnFloatBuffers) {
  for (GLenum type : {GL_FLOAT, GL_UNSIGNED_BYTE}) {
    TypedBuffer b(OSMESA_RGBA, type);
    ASSERT_TRUE(b.ok());
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    PixelOrtho();
    glEnable(GL_COLOR_SUM);
    glSecondaryColor3f(0.7f, 0.3f, 0.05f);
    Point(0, 0.8f, 0.2f, 0.1f, 0.5f);
    glSecondaryColor3f(1.5f, -0.5f, 0.3f);  // clamped: (1, 0, 0.3)
    Point(1, 0.8f, 0.2f, 0.1f, 0.5f);
    glDisable(GL_COLOR_SUM);
    Point(2, 0.8f, 0.2f, 0.1f, 0.5f);
    glFinish();
    EXPECT_NO_GL_ERROR();
    if (type == GL_FLOAT) {
      const float* p = b.f32();
      EXPECT_EQ(p[0], 0.8f + 0.7f);
      EXPECT_EQ(p[1], 0.2f + 0.3f);
      EXPECT_EQ(p[2], 0.1f + 0.05f);
      EXPECT_EQ(p[3], 0.5f);  // alpha is not summed
      EXPECT_EQ(p[4], 0.8f + 1.0f);
      EXPECT_EQ(p[5], 0.2f);
      EXPECT_EQ(p[6], 0.1f + 0.3f);
      EXPECT_EQ(p[8], 0.8f);
    } else {
      GLubyte ub[12] = {};
      glReadPixels(0, 0, 3, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
      const GLubyte want[12] = {255, 128, 38, 128, 255, 51, 102, 128, 204, 51, 26, 128};
      for (int i = 0; i < 12; ++i) EXPECT_EQ(ub[i], want[i]) << "type " << type << " byte " << i;
    }
  }
}

// B5G6R5: a clear rounds from float; a fragment goes through llvmpipe's 8
// bits (rint(c * 255), then the top bits): 0.123456 is byte 31, blue 3 (not
// the rounded 4); glReadPixels widens by bit replication.
TEST(OsmesaBufferTypeTest, Rgb565ClearDrawAndRead) {
  TypedBuffer b(OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5);
  ASSERT_TRUE(b.ok());
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClear(GL_COLOR_BUFFER_BIT);
  PixelOrtho();
  Point(1, 1.0f, 0.0f, 0.123456f, 1.0f);
  Point(2, 3.0f / 31.0f, 0.2f, 0.6f, 1.0f);
  glFinish();
  const uint16_t* p = b.u16();
  EXPECT_EQ(p[0], 0x19a9);  // 3, 13, 9
  EXPECT_EQ(p[1], 0xf803);  // 31, 0, 3
  GLubyte ub[4] = {};
  glReadPixels(2, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ub);
  const int r = p[2] >> 11, g = (p[2] >> 5) & 63, bl = p[2] & 31;
  EXPECT_EQ(ub[0], (r << 3) | (r >> 2));
  EXPECT_EQ(ub[1], (g << 2) | (g >> 4));
  EXPECT_EQ(ub[2], (bl << 3) | (bl >> 2));
  EXPECT_EQ(ub[3], 255);
  float fl[4] = {};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, fl);
  EXPECT_FLOAT_EQ(fl[0], 3.0f / 31.0f);
  EXPECT_FLOAT_EQ(fl[1], 13.0f / 63.0f);
  EXPECT_EQ(fl[3], 1.0f);
  EXPECT_NO_GL_ERROR();
}

// What Mesa writes into the client's memory, it writes at glFlush or
// glFinish: it renders into a buffer of its own. libglfixed renders into the
// client's memory at once, so after a glFinish both hold the same.
TEST(OsmesaBufferTypeTest, MemoryHoldsTheRenderingAfterGlFinish) {
  TypedBuffer b(OSMESA_RGBA, GL_UNSIGNED_SHORT);
  ASSERT_TRUE(b.ok());
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(b.u16()[0], 32768);
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(b.u16()[0], 6554);
}
