// The accumulation buffer (GL 2.1 §4.2.4): glAccum, glClearAccum, glClear of
// GL_ACCUM_BUFFER_BIT, their queries and errors. Built against Mesa too: the
// bytes expected are what Mesa's OSMesa returns (main/accum.c arithmetic:
// 16-bit signed values, truncated products, sums that wrap).
#include <cmath>

#include "gl_test_fixture.h"

namespace {

constexpr int kSize = 4;

class AccumTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(make(16)); }
  void TearDown() override { release(); }
  bool make(GLint accumBits) {
    release();
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, accumBits, NULL);
    return ctx_ && OSMesaMakeCurrent(ctx_, pixels_, GL_UNSIGNED_BYTE, kSize, kSize);
  }
  void release() {
    if (!ctx_) return;
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx_);
    ctx_ = nullptr;
  }
  static std::array<int, 4> pixel(int x = 1, int y = 1) {
    GLubyte p[4] = {};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return {p[0], p[1], p[2], p[3]};
  }
  static void clearColor(float r, float g, float b, float a) {
    glClearColor(r, g, b, a);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  OSMesaContext ctx_ = nullptr;
  GLubyte pixels_[kSize * kSize * 4] = {};
};

using Px = std::array<int, 4>;

TEST_F(AccumTest, SixteenBitsWheneverAsked) {
  for (GLint bits : {1, 8, 16, 32}) {
    ASSERT_TRUE(make(bits));
    for (GLenum p : {GL_ACCUM_RED_BITS, GL_ACCUM_GREEN_BITS, GL_ACCUM_BLUE_BITS, GL_ACCUM_ALPHA_BITS})
      EXPECT_EQ(glfx_test::GetInt(p), 16) << bits;
  }
  ASSERT_TRUE(make(0));
  EXPECT_EQ(glfx_test::GetInt(GL_ACCUM_RED_BITS), 0);
}

TEST_F(AccumTest, Errors) {
  glAccum(0x1234, 1.0f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  glAccum(GL_RETURN, 1.0f);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  ASSERT_TRUE(make(0));
  glAccum(0x1234, 1.0f);  // the op is checked before the buffer
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glClear(GL_ACCUM_BUFFER_BIT);  // no buffer: nothing to clear, no error
  EXPECT_NO_GL_ERROR();
}

TEST_F(AccumTest, ClearValueIsClampedToPlusMinusOne) {
  glClearAccum(0.5f, -0.25f, -3.0f, 2.0f);
  GLfloat v[4];
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, v);
  EXPECT_FLOAT_EQ(v[0], 0.5f);
  EXPECT_FLOAT_EQ(v[1], -0.25f);
  EXPECT_FLOAT_EQ(v[2], -1.0f);
  EXPECT_FLOAT_EQ(v[3], 1.0f);
  glPushAttrib(GL_ACCUM_BUFFER_BIT);
  glClearAccum(0, 0, 0, 0);
  glPopAttrib();
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, v);
  EXPECT_FLOAT_EQ(v[0], 0.5f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(AccumTest, ClearThenReturn) {
  glClearAccum(0.5f, -0.25f, 1.0f / 3, 1.0f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{127, 0, 85, 255}));
  glAccum(GL_RETURN, 2.0f);
  EXPECT_EQ(pixel(), (Px{255, 0, 170, 255}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(AccumTest, EveryOperation) {
  clearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_RETURN, 2.0f);
  EXPECT_EQ(pixel(), (Px{51, 102, 153, 204}));
  glAccum(GL_ACCUM, 0.3f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{41, 82, 122, 163}));
  glAccum(GL_MULT, 0.7f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{29, 57, 86, 114}));
  glAccum(GL_ADD, 0.01f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{31, 60, 88, 117}));
  // Past 32767 the sum wraps to negative values: black.
  glAccum(GL_ADD, 0.9f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{0, 0, 0, 0}));
  // -3 * 32767 truncated to 16 bits is -32765: it wraps back.
  glAccum(GL_ADD, -3.0f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{6, 34, 63, 91}));
  EXPECT_NO_GL_ERROR();
}

// Each byte loaded at a scale and returned at its inverse: where the
// truncation of the 16-bit products lands.
TEST_F(AccumTest, LoadAndReturnEveryByte) {
  for (float scale : {0.37f, 0.5f, 1.0f, 0.013f}) {
    for (int v = 0; v < 256; ++v) {
      const float f = static_cast<float>(v) / 255.0f;
      clearColor(f, f, f, f);
      glAccum(GL_LOAD, scale);
      glAccum(GL_RETURN, 1.0f / scale);
      const Px p = pixel();
      // What Mesa gives, computed the way it computes it.
      const float unorm = static_cast<float>(v) * (1.0f / 255.0f);
      const int acc = static_cast<int>(unorm * (scale * 32767.0f));
      const float back = static_cast<float>(acc) * ((1.0f / scale) / 32767.0f);
      const int expected = back > 1.0f ? 255 : static_cast<int>(std::nearbyint(back * 255.0f));
      ASSERT_EQ(p[0], expected) << "byte " << v << " scale " << scale;
    }
  }
}

TEST_F(AccumTest, OnlyTheScissorBoxAndTheWriteMask) {
  clearColor(1, 1, 1, 1);
  glAccum(GL_LOAD, 1.0f);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glAccum(GL_RETURN, 0.5f);
  EXPECT_EQ(pixel(0, 0), (Px{0, 0, 0, 0}));
  EXPECT_EQ(pixel(1, 0), (Px{128, 128, 128, 128}));
  // glAccum itself only touches the scissor box.
  glEnable(GL_SCISSOR_TEST);
  glScissor(2, 2, 2, 2);
  glAccum(GL_MULT, 0.0f);
  glDisable(GL_SCISSOR_TEST);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(3, 3), (Px{0, 0, 0, 0}));
  EXPECT_EQ(pixel(1, 1), (Px{255, 255, 255, 255}));
  // GL_RETURN writes only the channels of the colour mask.
  clearColor(0.1f, 0.1f, 0.1f, 0.1f);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glAccum(GL_RETURN, 0.5f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  EXPECT_EQ(pixel(1, 1), (Px{128, 26, 128, 26}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(AccumTest, CompiledIntoLists) {
  clearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glNewList(1, GL_COMPILE);
  glAccum(GL_LOAD, 1.0f);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_RETURN, 0.5f);
  glEndList();
  EXPECT_EQ(pixel(), (Px{51, 102, 153, 204}));  // nothing ran yet
  glCallList(1);
  EXPECT_EQ(pixel(), (Px{25, 51, 76, 102}));
  glDeleteLists(1, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(AccumTest, NothingInSelectMode) {
  clearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glAccum(GL_LOAD, 1.0f);
  GLuint names[4];
  glSelectBuffer(4, names);
  glRenderMode(GL_SELECT);
  glAccum(GL_MULT, 0.0f);
  glRenderMode(GL_RENDER);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(pixel(), (Px{51, 102, 153, 204}));
  EXPECT_NO_GL_ERROR();
}

}  // namespace

namespace {

// NaN and infinite values never crash, and what they give is Mesa's.
TEST_F(AccumTest, NonFiniteValues) {
  const float inf = INFINITY, nan = NAN;
  for (GLenum op : {GL_LOAD, GL_ACCUM, GL_MULT, GL_ADD, GL_RETURN})
    for (float v : {inf, -inf, nan, 1e30f, -1e30f}) {
      clearColor(0.2f, 0.4f, 0.6f, 0.8f);
      glAccum(GL_LOAD, 0.5f);
      glAccum(op, v);
      glAccum(GL_RETURN, 1.0f);
      const Px p = pixel();
      // Truncations past the 32-bit range give 0x80000000, whose low 16 bits are 0.
      if (op == GL_LOAD) EXPECT_EQ(p, (Px{0, 0, 0, 0})) << v;
      if (op == GL_RETURN) {
        clearColor(0.2f, 0.4f, 0.6f, 0.8f);
        glAccum(GL_LOAD, 0.5f);
        glAccum(GL_RETURN, v);
        const Px q = pixel();
        const int expected = v > 0 ? 255 : 0;  // NaN: lrintf's LONG_MIN, low byte 0
        EXPECT_EQ(q, (Px{expected, expected, expected, expected})) << v;
      }
    }
  glClearAccum(nan, inf, -inf, 0.5f);
  glClear(GL_ACCUM_BUFFER_BIT);
  glAccum(GL_RETURN, 1.0f);
  const Px p = pixel();
  EXPECT_EQ(p[1], 255);
  EXPECT_EQ(p[2], 0);
  EXPECT_EQ(p[3], 127);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
