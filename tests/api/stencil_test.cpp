// The stencil buffer and test (GL 2.1 §4.1.5, §4.2.3, §4.3.2): the buffer
// OSMesa allocates, glStencilFunc/Op/Mask and their Separate forms, their
// queries, errors, attribute group and display lists, glClearStencil and
// glClear with the write mask and scissor, glReadPixels of GL_STENCIL_INDEX
// and GL_DEPTH_STENCIL, every function and operation, and the face a
// primitive takes. Every expectation was measured on Mesa 22.3 (llvmpipe);
// the tests run on both.
#include "stencil_context.h"

#ifndef GL_DEPTH_STENCIL
#define GL_DEPTH_STENCIL 0x84F9
#endif
#ifndef GL_UNSIGNED_INT_24_8
#define GL_UNSIGNED_INT_24_8 0x84FA
#endif

namespace glfx_test {
namespace {


class StencilTest : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(c_.ok()); }
  StencilContext c_{24, 8};
};

int StencilAt(int x, int y) {
  GLubyte v = 0xee;
  glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &v);
  return v;
}

// A rectangle over pixels [x0, x1) x [y0, y1), counter-clockwise or not, at depth z.
void Rect(float x0, float y0, float x1, float y1, bool ccw = true, float z = 0) {
  glBegin(GL_QUADS);
  if (ccw) {
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
  } else {
    glVertex3f(x0, y0, z);
    glVertex3f(x0, y1, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x1, y0, z);
  }
  glEnd();
}

// ---- the buffer ---------------------------------------------------------------

TEST(StencilBufferTest, OsmesaGivesEightBitsWheneverAsked) {
  struct Case {
    int depth, stencil, depthBits, stencilBits;
  };
  const Case cases[] = {{0, 0, 0, 0},   {0, 1, 0, 8},   {0, 16, 0, 8},  {8, 0, 0, 0},   {8, 8, 24, 8},
                        {16, 0, 16, 0}, {16, 1, 24, 8}, {24, 0, 24, 0}, {24, 4, 24, 8}, {32, 8, 24, 8}};
  for (const Case& k : cases) {
    StencilContext c(k.depth, k.stencil);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(GetInt(GL_DEPTH_BITS), k.depthBits) << k.depth << "/" << k.stencil;
    EXPECT_EQ(GetInt(GL_STENCIL_BITS), k.stencilBits) << k.depth << "/" << k.stencil;
  }
  std::vector<unsigned char> buffer(16 * 16 * 4);
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 16, 16));
  EXPECT_EQ(GetInt(GL_STENCIL_BITS), 8);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

// Z24_UNORM_S8_UINT: the stencil is the top byte of the depth words
// OSMesaGetDepthBuffer hands out.
TEST_F(StencilTest, StencilIsTheTopByteOfTheDepthWords) {
  glClearStencil(0x5a);
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glFinish();
  GLint w = 0, h = 0, bytes = 0;
  void* p = nullptr;
  ASSERT_TRUE(OSMesaGetDepthBuffer(c_.get(), &w, &h, &bytes, &p));
  ASSERT_EQ(bytes, 4);
  uint32_t v;
  std::memcpy(&v, p, 4);
  EXPECT_EQ(v, 0x5a800000u);
  // A depth clear keeps the stencil, a stencil clear the depth.
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glFinish();
  std::memcpy(&v, p, 4);
  EXPECT_EQ(v, 0x5affffffu);
  glClearStencil(3);
  glClear(GL_STENCIL_BUFFER_BIT);
  glFinish();
  std::memcpy(&v, p, 4);
  EXPECT_EQ(v, 0x03ffffffu);
  // The depth test compares the 24 depth bits only and keeps the stencil.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  Rect(0, 0, 4, 4, true, 0);
  glFinish();
  std::memcpy(&v, p, 4);
  EXPECT_EQ(v >> 24, 3u);
  EXPECT_EQ(v & 0xffffff, 0x800000u);
}

// ---- state, queries, errors --------------------------------------------------

TEST_F(StencilTest, InitialState) {
  EXPECT_EQ(GetBool(GL_STENCIL_TEST), GL_FALSE);
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 0);
  EXPECT_EQ(GetInt(GL_STENCIL_VALUE_MASK), 0xff);  // Mesa: 0xff, not all ones
  EXPECT_EQ(GetInt(GL_STENCIL_WRITEMASK), 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(GetInt(GL_STENCIL_PASS_DEPTH_FAIL), GL_KEEP);
  EXPECT_EQ(GetInt(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FUNC), GL_ALWAYS);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_VALUE_MASK), 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_WRITEMASK), 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FAIL), GL_KEEP);
  EXPECT_EQ(GetInt(GL_STENCIL_CLEAR_VALUE), 0);
  EXPECT_EQ(GetFloat(GL_STENCIL_VALUE_MASK), 255.0f);
}

TEST_F(StencilTest, SettersAndQueries) {
  glStencilFunc(GL_LESS, 300, 0x1ff);
  glStencilMask(0x3ff);
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_LESS);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 255);  // clamped to the buffer's range
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_REF), 255);
  EXPECT_EQ(GetInt(GL_STENCIL_VALUE_MASK), 0x1ff);
  EXPECT_EQ(GetInt(GL_STENCIL_WRITEMASK), 0x3ff);
  glStencilFunc(GL_GEQUAL, -5, 0xffffffffu);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 0);
  EXPECT_EQ(GetInt(GL_STENCIL_VALUE_MASK), 2147483647);  // clamped to the integer range
  EXPECT_EQ(GetDouble(GL_STENCIL_VALUE_MASK), 4294967295.0);
  glStencilMask(0x80000000u);
  EXPECT_EQ(GetFloat(GL_STENCIL_WRITEMASK), 2147483648.0f);
  glClearStencil(0x1234);
  EXPECT_EQ(GetInt(GL_STENCIL_CLEAR_VALUE), 0x1234);

  glStencilFuncSeparate(GL_FRONT, GL_EQUAL, 10, 0x0f);
  glStencilFuncSeparate(GL_BACK, GL_NOTEQUAL, 20, 0xf0);
  glStencilOpSeparate(GL_FRONT, GL_ZERO, GL_INCR, GL_DECR);
  glStencilOpSeparate(GL_BACK, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP);
  glStencilMaskSeparate(GL_FRONT, 0x11);
  glStencilMaskSeparate(GL_BACK, 0x22);
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_EQUAL);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 10);
  EXPECT_EQ(GetInt(GL_STENCIL_VALUE_MASK), 0x0f);
  EXPECT_EQ(GetInt(GL_STENCIL_FAIL), GL_ZERO);
  EXPECT_EQ(GetInt(GL_STENCIL_PASS_DEPTH_FAIL), GL_INCR);
  EXPECT_EQ(GetInt(GL_STENCIL_PASS_DEPTH_PASS), GL_DECR);
  EXPECT_EQ(GetInt(GL_STENCIL_WRITEMASK), 0x11);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FUNC), GL_NOTEQUAL);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_REF), 20);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_VALUE_MASK), 0xf0);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FAIL), GL_INVERT);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_PASS_DEPTH_FAIL), GL_INCR_WRAP);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_DECR_WRAP);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_WRITEMASK), 0x22);
  glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_NEVER, 1, 2);
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_NEVER);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FUNC), GL_NEVER);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_VALUE_MASK), 2);
  glEnable(GL_STENCIL_TEST);
  EXPECT_EQ(GetBool(GL_STENCIL_TEST), GL_TRUE);
  EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
  EXPECT_NO_GL_ERROR();
}

TEST_F(StencilTest, Errors) {
  glStencilFunc(GL_LESS, 7, 0x0f);
  glStencilFunc(GL_ZERO, 0, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glStencilOp(GL_KEEP, GL_ALWAYS, GL_KEEP);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glStencilFuncSeparate(GL_NONE, GL_ALWAYS, 0, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glStencilOpSeparate(GL_FRONT_LEFT, GL_KEEP, GL_KEEP, GL_KEEP);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glStencilMaskSeparate(GL_LEFT, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_BACK, 0, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_TRIANGLES);
  glStencilFunc(GL_GREATER, 0, 0);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_TRIANGLES);
  glClearStencil(3);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  // Nothing changed.
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_LESS);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 7);
  EXPECT_EQ(GetInt(GL_STENCIL_VALUE_MASK), 0x0f);
  EXPECT_EQ(GetInt(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(GetInt(GL_STENCIL_WRITEMASK), 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_CLEAR_VALUE), 0);
}

TEST_F(StencilTest, AttribStackAndLists) {
  glPushAttrib(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_BACK, GL_LESS, 4, 0x7);
  glStencilOp(GL_ZERO, GL_REPLACE, GL_INVERT);
  glStencilMask(0x3);
  glClearStencil(9);
  glPopAttrib();
  EXPECT_EQ(GetBool(GL_STENCIL_TEST), GL_FALSE);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FUNC), GL_ALWAYS);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_VALUE_MASK), 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_FAIL), GL_KEEP);
  EXPECT_EQ(GetInt(GL_STENCIL_WRITEMASK), 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_CLEAR_VALUE), 0);

  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glStencilFunc(GL_EQUAL, 5, 0x3f);
  glStencilOp(GL_INCR, GL_DECR, GL_REPLACE);
  glStencilMask(0x0f);
  glStencilFuncSeparate(GL_BACK, GL_GREATER, 6, 0x1f);
  glStencilOpSeparate(GL_BACK, GL_INCR_WRAP, GL_DECR_WRAP, GL_ZERO);
  glStencilMaskSeparate(GL_BACK, 0x07);
  glClearStencil(0x42);
  glEndList();
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_ALWAYS);  // compiled, not run
  EXPECT_EQ(GetInt(GL_STENCIL_CLEAR_VALUE), 0);
  glCallList(list);
  EXPECT_EQ(GetInt(GL_STENCIL_FUNC), GL_EQUAL);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 5);
  EXPECT_EQ(GetInt(GL_STENCIL_PASS_DEPTH_PASS), GL_REPLACE);
  EXPECT_EQ(GetInt(GL_STENCIL_WRITEMASK), 0x0f);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FUNC), GL_GREATER);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_FAIL), GL_INCR_WRAP);
  EXPECT_EQ(GetInt(GL_STENCIL_BACK_WRITEMASK), 0x07);
  EXPECT_EQ(GetInt(GL_STENCIL_CLEAR_VALUE), 0x42);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

// ---- clear and read -------------------------------------------------------------

TEST_F(StencilTest, ClearWithWriteMaskAndScissor) {
  glClearStencil(0x81);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(0x0f);
  glClearStencil(0x3c);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 4, 4);
  glClear(GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_EQ(StencilAt(1, 1), 0x8c);
  EXPECT_EQ(StencilAt(10, 10), 0x81);
  // The front write mask is the one a clear uses.
  glStencilMaskSeparate(GL_FRONT, 0xff);
  glStencilMaskSeparate(GL_BACK, 0x00);
  glClearStencil(0x11);
  glClear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(StencilAt(1, 1), 0x11);
  glStencilMaskSeparate(GL_FRONT, 0x00);
  glStencilMaskSeparate(GL_BACK, 0xff);
  glClearStencil(0x22);
  glClear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(StencilAt(1, 1), 0x11);
  // Values past 8 bits keep their low byte.
  glStencilMask(0xff);
  glClearStencil(0x1234);
  glClear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(StencilAt(5, 5), 0x34);
}

TEST_F(StencilTest, ReadPixelsTypes) {
  glClearStencil(0x81);
  glClearDepth(0.25);
  glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const StencilInEveryType v = ReadStencilInEveryType(0, 0);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(v.ub, 0x81);
  EXPECT_EQ(v.us, 0x81);
  EXPECT_EQ(v.ui, 0x81u);
  EXPECT_EQ(v.f, 129.0f);
  EXPECT_EQ(v.b, 1);  // Mesa keeps 7 bits for GL_BYTE
  EXPECT_EQ(v.s, 129);
  EXPECT_EQ(v.i, 129);
  GLuint ds = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(ds, 0x40000081u);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, &ds);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT_24_8, &ds);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  // Index shift and offset apply, on 8-bit values.
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 3);
  const StencilInEveryType shifted = ReadStencilInEveryType(0, 0);
  EXPECT_EQ(shifted.ub, 5);
  EXPECT_EQ(shifted.us, 5);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  // A block of values, rows bottom first.
  glStencilFunc(GL_ALWAYS, 0x21, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glEnable(GL_STENCIL_TEST);
  Rect(1, 0, 2, 1);
  GLubyte row[4] = {0, 0, 0, 0};
  glReadPixels(0, 0, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, row);
  EXPECT_EQ(row[0], 0x81);
  EXPECT_EQ(row[1], 0x21);
  EXPECT_EQ(row[2], 0x81);
}

TEST(StencilBufferTest, WithoutAStencilBuffer) {
  StencilContext c(24, 0);
  ASSERT_TRUE(c.ok());
  glStencilFunc(GL_LESS, 5, 0xff);
  EXPECT_EQ(GetInt(GL_STENCIL_REF), 0);
  EXPECT_EQ(GetInt(GL_STENCIL_VALUE_MASK), 0xff);
  GLuint v = 0;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  // The test passes without a buffer (GL 2.1 §4.1.5).
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 0, 0xff);
  glColor3f(1, 0, 0);
  Rect(0, 0, 4, 4);
  EXPECT_EQ(c.pixel(2, 2)[0], 255);
}

TEST(StencilBufferTest, StencilWithoutDepth) {
  StencilContext c(0, 8);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(GetInt(GL_STENCIL_BITS), 8);
  GLint w, h, bytes;
  void* p;
  EXPECT_FALSE(OSMesaGetDepthBuffer(c.get(), &w, &h, &bytes, &p));
  glClearStencil(7);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);  // no depth buffer: the depth test passes
  glStencilOp(GL_INCR, GL_INCR, GL_INVERT);
  glStencilFunc(GL_EQUAL, 7, 0xff);
  Rect(0, 0, 4, 4);
  EXPECT_EQ(StencilAt(2, 2), 0xf8);
  EXPECT_EQ(StencilAt(6, 6), 7);
  Rect(0, 0, 4, 4);  // now fails: INCR
  EXPECT_EQ(StencilAt(2, 2), 0xf9);
  GLuint v;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

// ---- the test and its operations ---------------------------------------------

// Each operation on each stored value, under a write mask.
TEST_F(StencilTest, EveryOperation) {
  const GLenum ops[] = {GL_KEEP, GL_ZERO,   GL_REPLACE,   GL_INCR,
                        GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
  const int stored[] = {0, 1, 0x7f, 0x80, 0xfe, 0xff};
  glEnable(GL_STENCIL_TEST);
  for (GLuint writeMask : {0xffu, 0x0fu, 0x1f0u}) {
    for (GLenum op : ops) {
      for (int s0 : stored) {
        glStencilMask(0xff);
        glClearStencil(s0);
        glClear(GL_STENCIL_BUFFER_BIT);
        glStencilMask(writeMask);
        glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, op);
        Rect(0, 0, 2, 2);
        int r = s0;
        switch (op) {
          case GL_ZERO: r = 0; break;
          case GL_REPLACE: r = 0x5a; break;
          case GL_INCR: r = s0 < 255 ? s0 + 1 : 255; break;
          case GL_DECR: r = s0 > 0 ? s0 - 1 : 0; break;
          case GL_INVERT: r = ~s0 & 0xff; break;
          case GL_INCR_WRAP: r = (s0 + 1) & 0xff; break;
          case GL_DECR_WRAP: r = (s0 - 1) & 0xff; break;
          default: break;
        }
        const int m = static_cast<int>(writeMask & 0xff);
        EXPECT_EQ(StencilAt(1, 1), (s0 & ~m) | (r & m))
            << "op 0x" << std::hex << op << " stored " << s0 << " mask " << writeMask;
        EXPECT_EQ(StencilAt(3, 3), s0);
      }
    }
  }
}

// Each function against each stored value, with a value mask: the fragment
// is drawn where (ref & mask) func (stored & mask).
TEST_F(StencilTest, EveryFunction) {
  const GLenum funcs[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                          GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  const int stored[] = {0, 0x30, 0x3f, 0x40, 0xc0, 0xff};
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  for (GLuint mask : {0xffu, 0x3fu}) {
    for (GLenum func : funcs) {
      for (int s0 : stored) {
        for (int ref : {0x3f, 0x140, -1}) {
          glClearStencil(s0);
          glClearColor(0, 0, 0, 0);
          glClear(GL_STENCIL_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
          glStencilFunc(func, ref, mask);
          glColor3f(1, 1, 1);
          Rect(0, 0, 2, 2);
          const int r = (ref < 0 ? 0 : ref > 255 ? 255 : ref) & static_cast<int>(mask & 0xff);
          const int s = s0 & static_cast<int>(mask & 0xff);
          bool pass = false;
          switch (func) {
            case GL_LESS: pass = r < s; break;
            case GL_EQUAL: pass = r == s; break;
            case GL_LEQUAL: pass = r <= s; break;
            case GL_GREATER: pass = r > s; break;
            case GL_NOTEQUAL: pass = r != s; break;
            case GL_GEQUAL: pass = r >= s; break;
            case GL_ALWAYS: pass = true; break;
            default: break;
          }
          EXPECT_EQ(c_.pixel(1, 1)[0], pass ? 255 : 0)
              << "func 0x" << std::hex << func << " ref " << ref << " stored " << s0 << " mask " << mask;
        }
      }
    }
  }
}

// Stencil fail, depth fail, depth pass: each fragment takes its outcome's operation.
TEST_F(StencilTest, OperationByOutcome) {
  glClearStencil(0x10);
  glClearDepth(1.0);
  glClear(GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  Rect(0, 0, 8, 8, true, 0.0f);  // depth 0.5 where x < 8
  glStencilFunc(GL_EQUAL, 0x10, 0xff);
  glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
  Rect(0, 0, 16, 4, true, -0.5f);  // depth 0.75, behind the first rect where x < 8: depth fail
  EXPECT_EQ(StencilAt(2, 2), 0x0f);
  EXPECT_EQ(StencilAt(10, 2), 0xef);
  Rect(0, 0, 16, 4, true, 0.5f);  // in front, but the stencil differs now: stencil fail
  EXPECT_EQ(StencilAt(2, 2), 0x10);
  EXPECT_EQ(StencilAt(10, 2), 0xf0);
  // Without the depth test every stencil pass takes the depth-pass operation.
  glDisable(GL_DEPTH_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  Rect(0, 4, 16, 8, true, -0.5f);
  EXPECT_EQ(StencilAt(2, 6), 0xef);
  EXPECT_EQ(StencilAt(10, 6), 0xef);
  // The depth mask leaves the depth, not the stencil.
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  Rect(0, 8, 16, 12, true, 0.5f);
  EXPECT_EQ(StencilAt(10, 10), 0xef);
  GLuint d = 0;
  glReadPixels(10, 10, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &d);
  EXPECT_EQ(d, 0xffffffffu);
}

// Triangles take the state of their face, by their winding and glFrontFace;
// points and lines (also of GL_LINE and GL_POINT polygons, and smooth lines)
// face front; a smooth point's quad faces back.
TEST_F(StencilTest, FacingPicksTheState) {
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_FRONT, GL_ALWAYS, 10, 0xff);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 20, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glClear(GL_STENCIL_BUFFER_BIT);
  Rect(0, 0, 4, 4, true);
  Rect(8, 0, 12, 4, false);
  glFrontFace(GL_CW);
  Rect(16, 0, 20, 4, true);
  Rect(24, 0, 28, 4, false);
  glFrontFace(GL_CCW);
  EXPECT_EQ(StencilAt(2, 2), 10);
  EXPECT_EQ(StencilAt(10, 2), 20);
  EXPECT_EQ(StencilAt(18, 2), 20);
  EXPECT_EQ(StencilAt(26, 2), 10);
  glBegin(GL_POINTS);
  glVertex2f(12.5f, 12.5f);
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(20, 12.5f);
  glVertex2f(30, 12.5f);
  glEnd();
  glPolygonMode(GL_BACK, GL_LINE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0.5f, 20.5f);
  glVertex2f(0.5f, 30.5f);
  glVertex2f(10.5f, 20.5f);
  glEnd();
  glPolygonMode(GL_BACK, GL_POINT);
  glBegin(GL_TRIANGLES);
  glVertex2f(12.5f, 20.5f);
  glVertex2f(12.5f, 30.5f);
  glVertex2f(22.5f, 20.5f);
  glEnd();
  glPolygonMode(GL_BACK, GL_FILL);
  EXPECT_EQ(StencilAt(12, 12), 10);
  EXPECT_EQ(StencilAt(25, 12), 10);
  EXPECT_EQ(StencilAt(5, 20), 10);
  EXPECT_EQ(StencilAt(12, 20), 10);
  glEnable(GL_LINE_SMOOTH);
  glBegin(GL_LINES);
  glVertex2f(40, 20.5f);
  glVertex2f(50, 20.5f);
  glVertex2f(50, 24.5f);
  glVertex2f(40, 24.5f);
  glEnd();
  glDisable(GL_LINE_SMOOTH);
  EXPECT_EQ(StencilAt(45, 20), 10);
  EXPECT_EQ(StencilAt(45, 24), 10);
  glEnable(GL_POINT_SMOOTH);
  glPointSize(4);
  glBegin(GL_POINTS);
  glVertex2f(40, 40);
  glEnd();
  glFrontFace(GL_CW);
  glBegin(GL_POINTS);
  glVertex2f(50, 40);
  glEnd();
  EXPECT_EQ(StencilAt(40, 40), 20);
  EXPECT_EQ(StencilAt(50, 40), 20);  // whatever glFrontFace says
}

// Two-sided: GL_INCR_WRAP on front faces and GL_DECR_WRAP on back ones of a
// closed shape leave the buffer as it was (shadow volumes).
TEST_F(StencilTest, TwoSidedWrapCancels) {
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  glClear(GL_STENCIL_BUFFER_BIT);
  Rect(0, 0, 8, 8, false);
  EXPECT_EQ(StencilAt(4, 4), 255);
  Rect(0, 0, 8, 8, false);
  EXPECT_EQ(StencilAt(4, 4), 254);
  Rect(0, 0, 8, 8, true);
  Rect(0, 0, 8, 8, true);
  Rect(0, 0, 8, 8, true);
  EXPECT_EQ(StencilAt(4, 4), 1);
}

// ---- EXT_stencil_two_side and ATI_separate_stencil ------------------------------
// Mesa keeps three faces (stencil.c): front, the GL 2.0 back face and the
// EXT back face, which back faces use while GL_STENCIL_TEST_TWO_SIDE_EXT is on.

constexpr GLenum kStencilTestTwoSideEXT = 0x8910, kActiveStencilFaceEXT = 0x8911;
using ActiveStencilFace = void(APIENTRY*)(GLenum);
using StencilFuncSeparateATI = void(APIENTRY*)(GLenum, GLenum, GLint, GLuint);
using StencilOpSeparateATI = void(APIENTRY*)(GLenum, GLenum, GLenum, GLenum);

int Integer(GLenum pname) {
  GLint v = -1;
  glGetIntegerv(pname, &v);
  return v;
}

TEST_F(StencilTest, ActiveFaceExtAddressesItsOwnBackFace) {
  auto activeFace = reinterpret_cast<ActiveStencilFace>(OSMesaGetProcAddress("glActiveStencilFaceEXT"));
  ASSERT_NE(activeFace, nullptr);
  EXPECT_EQ(Integer(kActiveStencilFaceEXT), GL_FRONT);
  EXPECT_FALSE(glIsEnabled(kStencilTestTwoSideEXT));
  activeFace(GL_BACK);
  glStencilFunc(GL_LESS, 5, 0x0f);
  glStencilMask(0x3);
  glStencilOp(GL_INCR, GL_KEEP, GL_KEEP);
  // The plain queries read the active face; the GL 2.0 back face is untouched.
  EXPECT_EQ(Integer(kActiveStencilFaceEXT), GL_BACK);
  EXPECT_EQ(Integer(GL_STENCIL_FUNC), GL_LESS);
  EXPECT_EQ(Integer(GL_STENCIL_REF), 5);
  EXPECT_EQ(Integer(GL_STENCIL_VALUE_MASK), 0x0f);
  EXPECT_EQ(Integer(GL_STENCIL_WRITEMASK), 0x3);
  EXPECT_EQ(Integer(GL_STENCIL_FAIL), GL_INCR);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_FUNC), GL_ALWAYS);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_WRITEMASK), 0xff);
  activeFace(GL_FRONT);
  EXPECT_EQ(Integer(GL_STENCIL_FUNC), GL_ALWAYS);
  EXPECT_EQ(Integer(GL_STENCIL_WRITEMASK), 0xff);
  EXPECT_GL_ERROR(GL_NO_ERROR);
  activeFace(GL_FRONT_AND_BACK);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  activeFace(GL_BACK);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(Integer(kActiveStencilFaceEXT), GL_FRONT);
}

TEST_F(StencilTest, TwoSideExtPicksTheBackFace) {
  auto activeFace = reinterpret_cast<ActiveStencilFace>(OSMesaGetProcAddress("glActiveStencilFaceEXT"));
  ASSERT_NE(activeFace, nullptr);
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  activeFace(GL_BACK);
  glStencilFunc(GL_ALWAYS, 2, 0xff);
  glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
  activeFace(GL_FRONT);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 3, 0xff);
  for (int twoSide = 0; twoSide < 2; ++twoSide) {
    if (twoSide)
      glEnable(kStencilTestTwoSideEXT);
    else
      glDisable(kStencilTestTwoSideEXT);
    glClear(GL_STENCIL_BUFFER_BIT);
    Rect(0, 0, 4, 4, true);
    Rect(8, 0, 12, 4, false);
    EXPECT_EQ(StencilAt(2, 2), 1) << twoSide;
    EXPECT_EQ(StencilAt(10, 2), twoSide ? 2 : 3) << twoSide;
  }
  // glClear takes the front write mask whichever face is active.
  activeFace(GL_BACK);
  glStencilMask(0x0f);
  activeFace(GL_FRONT);
  glStencilMask(0xf0);
  activeFace(GL_BACK);
  glClearStencil(0xff);
  glClear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(StencilAt(10, 2), 0xf2);
}

TEST_F(StencilTest, TwoSideStateInAttribStackAndLists) {
  auto activeFace = reinterpret_cast<ActiveStencilFace>(OSMesaGetProcAddress("glActiveStencilFaceEXT"));
  auto funcATI = reinterpret_cast<StencilFuncSeparateATI>(OSMesaGetProcAddress("glStencilFuncSeparateATI"));
  auto opATI = reinterpret_cast<StencilOpSeparateATI>(OSMesaGetProcAddress("glStencilOpSeparateATI"));
  ASSERT_NE(activeFace, nullptr);
  ASSERT_NE(funcATI, nullptr);
  ASSERT_NE(opATI, nullptr);
  glEnable(kStencilTestTwoSideEXT);
  funcATI(GL_GREATER, GL_EQUAL, 7, 0xf0);
  EXPECT_EQ(Integer(GL_STENCIL_FUNC), GL_GREATER);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_FUNC), GL_EQUAL);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_REF), 7);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_VALUE_MASK), 0xf0);
  funcATI(GL_GREATER, GL_FRONT, 7, 0xf0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  opATI(GL_BACK, GL_ZERO, GL_REPLACE, GL_INVERT);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_FAIL), GL_ZERO);
  EXPECT_EQ(Integer(GL_STENCIL_FAIL), GL_KEEP);
  glPushAttrib(GL_STENCIL_BUFFER_BIT);
  activeFace(GL_BACK);
  glDisable(kStencilTestTwoSideEXT);
  glPopAttrib();
  EXPECT_EQ(Integer(kActiveStencilFaceEXT), GL_FRONT);
  EXPECT_TRUE(glIsEnabled(kStencilTestTwoSideEXT));
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(kStencilTestTwoSideEXT);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(kStencilTestTwoSideEXT));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  activeFace(GL_BACK);
  glStencilFunc(GL_NOTEQUAL, 9, 0xff);
  funcATI(GL_LEQUAL, GL_GEQUAL, 3, 0x7);
  glEndList();
  EXPECT_EQ(Integer(kActiveStencilFaceEXT), GL_FRONT);
  EXPECT_EQ(Integer(GL_STENCIL_FUNC), GL_GREATER);
  glCallList(list);
  EXPECT_EQ(Integer(kActiveStencilFaceEXT), GL_BACK);
  EXPECT_EQ(Integer(GL_STENCIL_FUNC), GL_NOTEQUAL);
  EXPECT_EQ(Integer(GL_STENCIL_REF), 9);
  EXPECT_EQ(Integer(GL_STENCIL_BACK_FUNC), GL_GEQUAL);
  activeFace(GL_FRONT);
  EXPECT_EQ(Integer(GL_STENCIL_FUNC), GL_LEQUAL);
  EXPECT_EQ(Integer(GL_STENCIL_REF), 3);
  glDeleteLists(list, 1);
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

}  // namespace
}  // namespace glfx_test
