// Blending and the logic op (GL 2.1 §4.1.8, §4.1.10): glBlendFunc,
// glBlendFuncSeparate, glBlendEquation(Separate), glBlendColor, glLogicOp,
// GL_BLEND, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP, GL_DITHER: defaults,
// queries, errors, the attribute stack, display lists, the extension names,
// and the bytes llvmpipe's 8-bit blending writes. Passes on Mesa too.
#include <algorithm>
#include <cstring>
#include <string>

#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

class BlendTest : public GLTest {
 protected:
  // One pixel at (x, y) of the bottom-left quarter: glRect in pixel units.
  void SetUp() override {
    GLTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
  }
  // Clears to `dst` (bytes), draws a 4x4 rectangle of `src` (bytes, flat)
  // and returns the bytes read back at its centre.
  std::array<int, 4> draw(const std::array<int, 4>& dst, const std::array<int, 4>& src) {
    glClearColor(dst[0] / 255.0f, dst[1] / 255.0f, dst[2] / 255.0f, dst[3] / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4ub(GLubyte(src[0]), GLubyte(src[1]), GLubyte(src[2]), GLubyte(src[3]));
    glRectf(8, 8, 12, 12);
    GLubyte p[4] = {};
    glReadPixels(10, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return {p[0], p[1], p[2], p[3]};
  }
};

// llvmpipe's product of two bytes, t / 255 rounded as (t + (t >> 8) + 128) >> 8.
int mul8(int a, int b) {
  const int t = a * b;
  return (t + (t >> 8) + 128) >> 8;
}

TEST_F(BlendTest, Defaults) {
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_LOGIC_OP), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_INDEX_LOGIC_OP), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(GetInt(GL_BLEND_SRC), GL_ONE);
  EXPECT_EQ(GetInt(GL_BLEND_DST), GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(GetInt(GL_BLEND_DST_RGB), GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_ALPHA), GL_ONE);
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION), GL_FUNC_ADD);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_ALPHA), GL_FUNC_ADD);
  EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), GL_COPY);
  const std::array<GLfloat, 4> c = GetFloats<4>(GL_BLEND_COLOR);
  for (GLfloat v : c) EXPECT_EQ(v, 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, SettersAndQueries) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
  EXPECT_EQ(GetInt(GL_BLEND_SRC), GL_SRC_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_DST), GL_ONE_MINUS_SRC_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_ALPHA), GL_SRC_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_ONE_MINUS_SRC_ALPHA);
  glBlendFuncSeparate(GL_DST_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_DST_COLOR);
  EXPECT_EQ(GetInt(GL_BLEND_DST_RGB), GL_ONE_MINUS_CONSTANT_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_ALPHA), GL_SRC_ALPHA_SATURATE);
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_CONSTANT_COLOR);
  for (GLenum e : {GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX, GL_FUNC_ADD}) {
    glBlendEquation(e);
    EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), static_cast<GLint>(e));
    EXPECT_EQ(GetInt(GL_BLEND_EQUATION_ALPHA), static_cast<GLint>(e));
  }
  glBlendEquationSeparate(GL_MIN, GL_FUNC_REVERSE_SUBTRACT);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), GL_MIN);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_ALPHA), GL_FUNC_REVERSE_SUBTRACT);
  for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
    glLogicOp(op);
    EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), static_cast<GLint>(op));
  }
  glEnable(GL_COLOR_LOGIC_OP);
  EXPECT_EQ(GetBool(GL_COLOR_LOGIC_OP), GL_TRUE);
  glEnable(GL_LOGIC_OP);  // GL 1.0's name of GL_INDEX_LOGIC_OP
  EXPECT_EQ(glIsEnabled(GL_INDEX_LOGIC_OP), GL_TRUE);
  glDisable(GL_DITHER);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, BlendColorIsClampedWhenQueried) {
  glBlendColor(2.0f, -1.0f, 0.5f, 0.25f);
  const std::array<GLfloat, 4> c = GetFloats<4>(GL_BLEND_COLOR);
  EXPECT_EQ(c[0], 1.0f);
  EXPECT_EQ(c[1], 0.0f);
  EXPECT_EQ(c[2], 0.5f);
  EXPECT_EQ(c[3], 0.25f);
  GLint i[4];
  glGetIntegerv(GL_BLEND_COLOR, i);
  EXPECT_EQ(i[0], 2147483647);
  EXPECT_EQ(i[1], 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, ErrorsChangeNothing) {
  glBlendFunc(GL_SRC_ALPHA, GL_ONE);
  glBlendFunc(GL_SRC_ALPHA, GL_FUNC_ADD);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBlendFunc(0x1234, GL_ONE);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_ONE);
  glBlendEquation(GL_LOGIC_OP);  // EXT_blend_logic_op's equation: not offered
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBlendEquation(GL_ONE);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBlendEquationSeparate(GL_FUNC_ADD, GL_SRC_ALPHA);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
  glLogicOp(GL_XOR);
  glLogicOp(GL_CLEAR - 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glLogicOp(GL_SET + 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), GL_XOR);
  glBegin(GL_POINTS);
  glBlendFunc(GL_ONE, GL_ONE);
  glBlendEquation(GL_MAX);
  glBlendColor(1, 1, 1, 1);
  glLogicOp(GL_AND);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
  EXPECT_EQ(GetFloat(GL_BLEND_COLOR), 0.0f);
  EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), GL_XOR);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, PushAttribRestoresColorBufferState) {
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glEnable(GL_COLOR_LOGIC_OP);
  glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_DST_ALPHA, GL_ONE);
  glBlendEquationSeparate(GL_MAX, GL_MIN);
  glBlendColor(0.1f, 0.2f, 0.3f, 0.4f);
  glLogicOp(GL_NAND);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_LOGIC_OP), GL_FALSE);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_ALPHA), GL_FUNC_ADD);
  EXPECT_EQ(GetFloat(GL_BLEND_COLOR), 0.0f);
  EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), GL_COPY);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_BLEND);
  glEnable(GL_COLOR_LOGIC_OP);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_LOGIC_OP), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, DisplayListsHoldTheCommands) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_SRC_ALPHA);
  glBlendEquation(GL_MIN);
  glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
  glBlendColor(0.5f, 0.5f, 0.5f, 0.5f);
  glLogicOp(GL_OR);
  glEndList();
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_ONE);  // compiled, not run
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
  EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), GL_COPY);
  glCallList(list);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_ONE);
  EXPECT_EQ(GetInt(GL_BLEND_DST_RGB), GL_ONE);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_ALPHA), GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_DST_ALPHA), GL_SRC_ALPHA);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  EXPECT_EQ(GetInt(GL_BLEND_EQUATION_ALPHA), GL_MAX);
  EXPECT_EQ(GetFloat(GL_BLEND_COLOR), 0.5f);
  EXPECT_EQ(GetInt(GL_LOGIC_OP_MODE), GL_OR);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, ExtensionNamesAndCommands) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  for (const char* name : {"GL_EXT_blend_color", "GL_EXT_blend_minmax", "GL_EXT_blend_subtract",
                           "GL_EXT_blend_func_separate", "GL_EXT_blend_equation_separate"})
    EXPECT_NE(ext.find(std::string(name) + " "), std::string::npos) << name;
  for (const char* name : {"glBlendColorEXT", "glBlendEquationEXT", "glBlendFuncSeparateEXT",
                           "glBlendFuncSeparateINGR", "glBlendEquationSeparateEXT"})
    EXPECT_NE(reinterpret_cast<void*>(OSMesaGetProcAddress(name)), nullptr) << name;
  typedef void (*Separate)(GLenum, GLenum, GLenum, GLenum);
  const Separate ext4 = reinterpret_cast<Separate>(OSMesaGetProcAddress("glBlendFuncSeparateEXT"));
  ASSERT_NE(ext4, nullptr);
  ext4(GL_SRC_COLOR, GL_DST_COLOR, GL_ONE, GL_ZERO);
  EXPECT_EQ(GetInt(GL_BLEND_SRC_RGB), GL_SRC_COLOR);
  EXPECT_EQ(GetInt(GL_BLEND_DST_RGB), GL_DST_COLOR);
  EXPECT_NO_GL_ERROR();
}

// The bytes: 8-bit products rounded as llvmpipe's, saturating add and
// subtract, min and max without factors.
TEST_F(BlendTest, BytesOfEachEquation) {
  glEnable(GL_BLEND);
  const std::array<int, 4> dst = {200, 100, 30, 80}, src = {120, 60, 240, 170};
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  std::array<int, 4> got = draw(dst, src);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], mul8(src[k], 170) + mul8(dst[k], 255 - 170)) << k;
  glBlendFunc(GL_ONE, GL_ONE);
  got = draw(dst, src);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], std::min(255, src[k] + dst[k])) << k;
  glBlendEquation(GL_FUNC_SUBTRACT);
  got = draw(dst, src);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], std::max(0, src[k] - dst[k])) << k;
  glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
  got = draw(dst, src);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], std::max(0, dst[k] - src[k])) << k;
  glBlendFunc(GL_ZERO, GL_ZERO);  // MIN and MAX ignore the factors
  glBlendEquation(GL_MIN);
  got = draw(dst, src);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], std::min(src[k], dst[k])) << k;
  glBlendEquation(GL_MAX);
  got = draw(dst, src);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got[k], std::max(src[k], dst[k])) << k;
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE_MINUS_DST_COLOR);
  got = draw(dst, src);
  const int f = std::min(170, 255 - 80);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(got[k], std::min(255, mul8(src[k], f) + mul8(dst[k], 255 - dst[k]))) << k;
  EXPECT_EQ(got[3], std::min(255, src[3] + mul8(dst[3], 255 - dst[3])));
  EXPECT_NO_GL_ERROR();
}

// 152 * 229 / 255 = 136.5...: llvmpipe's rounding gives 136 where the
// exact rounding would give 137. The constant colour is 8 bits, rounded to
// nearest even (0.5 -> 128 from 127.5).
TEST_F(BlendTest, ProductRoundingAndTheConstantColour) {
  glEnable(GL_BLEND);
  glBlendColor(229 / 255.0f, 0.5f, 0.3f, 1.0f);
  glBlendFunc(GL_ZERO, GL_CONSTANT_COLOR);
  const std::array<int, 4> got = draw({152, 255, 255, 255}, {0, 0, 0, 0});
  EXPECT_EQ(got[0], mul8(152, 229));
  EXPECT_EQ(got[0], 136);
  EXPECT_EQ(got[1], 128);
  EXPECT_EQ(got[2], 76);  // 0.3f * 255 = 76.5 -> 76
  EXPECT_EQ(got[3], 255);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, LogicOpsReplaceBlending) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_COLOR_LOGIC_OP);
  const std::array<int, 4> dst = {0xc3, 0x5a, 0x0f, 0xf0}, src = {0xa5, 0x3c, 0xff, 0x00};
  for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
    glLogicOp(op);
    const std::array<int, 4> got = draw(dst, src);
    for (int k = 0; k < 4; ++k) {
      const int s = src[k], d = dst[k];
      int want = 0;
      switch (op) {
        case GL_CLEAR: want = 0; break;
        case GL_AND: want = s & d; break;
        case GL_AND_REVERSE: want = s & ~d; break;
        case GL_COPY: want = s; break;
        case GL_AND_INVERTED: want = ~s & d; break;
        case GL_NOOP: want = d; break;
        case GL_XOR: want = s ^ d; break;
        case GL_OR: want = s | d; break;
        case GL_NOR: want = ~(s | d); break;
        case GL_EQUIV: want = ~(s ^ d); break;
        case GL_INVERT: want = ~d; break;
        case GL_OR_REVERSE: want = s | ~d; break;
        case GL_COPY_INVERTED: want = ~s; break;
        case GL_OR_INVERTED: want = ~s | d; break;
        case GL_NAND: want = ~(s & d); break;
        default: want = 255; break;
      }
      EXPECT_EQ(got[k], want & 255) << "op 0x" << std::hex << op << " channel " << k;
    }
  }
  // GL_INDEX_LOGIC_OP does nothing in RGBA mode: blending applies.
  glDisable(GL_COLOR_LOGIC_OP);
  glEnable(GL_INDEX_LOGIC_OP);
  glLogicOp(GL_XOR);
  const std::array<int, 4> got = draw({10, 20, 30, 40}, {1, 2, 3, 4});
  EXPECT_EQ(got[0], 11);
  EXPECT_EQ(got[3], 44);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BlendTest, DitherChangesNothing) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_DITHER);
  const std::array<int, 4> a = draw({13, 77, 201, 90}, {99, 150, 7, 133});
  glDisable(GL_DITHER);
  const std::array<int, 4> b = draw({13, 77, 201, 90}, {99, 150, 7, 133});
  EXPECT_EQ(a, b);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
