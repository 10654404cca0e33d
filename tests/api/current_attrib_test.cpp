// The current colour and normal (GL 2.1 §2.7): every glColor{3,4}* and
// glNormal3* variant, with the integer-to-float conversions of table 2.9:
//   unsigned, b bits: c / (2^b - 1)
//   signed,   b bits: (2c + 1) / (2^b - 1)
// (GL 4.2 changed the signed rule to max(c / (2^(b-1) - 1), -1); Mesa 22 keeps
// the GL 2.1 rule for glColor and glNormal.) Floats are stored as given: the
// current colour is not clamped (clamping happens after lighting, §2.14.6).
#include <climits>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using CurrentAttribTest = GLTest;

double U(double c, int bits) { return c / (std::ldexp(1.0, bits) - 1.0); }
double S(double c, int bits) { return (2.0 * c + 1.0) / (std::ldexp(1.0, bits) - 1.0); }

void ExpectColor(const char* what, double r, double g, double b, double a) {
  SCOPED_TRACE(what);
  std::array<GLfloat, 4> f = GetFloats<4>(GL_CURRENT_COLOR);
  std::array<GLdouble, 4> d = GetDoubles<4>(GL_CURRENT_COLOR);
  const double e[4] = {r, g, b, a};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(f[k], e[k], 2e-7 * std::fmax(1.0, std::fabs(e[k]))) << "glGetFloatv, channel " << k;
    EXPECT_NEAR(d[k], e[k], 2e-7 * std::fmax(1.0, std::fabs(e[k]))) << "glGetDoublev, channel " << k;
  }
  EXPECT_NO_GL_ERROR();
}

void ExpectNormal(const char* what, double x, double y, double z) {
  SCOPED_TRACE(what);
  std::array<GLfloat, 3> f = GetFloats<3>(GL_CURRENT_NORMAL);
  std::array<GLdouble, 3> d = GetDoubles<3>(GL_CURRENT_NORMAL);
  const double e[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(f[k], e[k], 2e-7 * std::fmax(1.0, std::fabs(e[k]))) << "glGetFloatv, coordinate " << k;
    EXPECT_NEAR(d[k], e[k], 2e-7 * std::fmax(1.0, std::fabs(e[k]))) << "glGetDoublev, coordinate " << k;
  }
  EXPECT_NO_GL_ERROR();
}

// Resets the current colour to something no case below produces.
void Reset() {
  glColor4f(-9, -9, -9, -9);
  // Mesa bug: a glColor3* right after glColor4* can leave the old alpha
  // (Color3AfterColor4SetsAlphaToOne); a flush between them avoids it.
  if (kTestingAgainstMesa) glFlush();
}

TEST_F(CurrentAttribTest, ColorUnsignedByte) {
  const GLubyte v[4] = {0, 255, 128, 1};
  glColor4ub(v[0], v[1], v[2], v[3]);
  ExpectColor("glColor4ub", U(0, 8), U(255, 8), U(128, 8), U(1, 8));
  Reset();
  glColor4ubv(v);
  ExpectColor("glColor4ubv", U(0, 8), U(255, 8), U(128, 8), U(1, 8));
  Reset();
  glColor3ub(v[3], v[2], v[1]);
  ExpectColor("glColor3ub", U(1, 8), U(128, 8), U(255, 8), 1.0);
  Reset();
  glColor3ubv(v);
  ExpectColor("glColor3ubv", U(0, 8), U(255, 8), U(128, 8), 1.0);
}

TEST_F(CurrentAttribTest, ColorSignedByte) {
  const GLbyte v[4] = {-128, 127, 0, 64};
  glColor4b(v[0], v[1], v[2], v[3]);
  ExpectColor("glColor4b", -1.0, 1.0, S(0, 8), S(64, 8));
  Reset();
  glColor4bv(v);
  ExpectColor("glColor4bv", -1.0, 1.0, S(0, 8), S(64, 8));
  Reset();
  glColor3b(v[2], v[3], v[0]);
  ExpectColor("glColor3b", S(0, 8), S(64, 8), -1.0, 1.0);
  Reset();
  glColor3bv(v + 1);
  ExpectColor("glColor3bv", 1.0, S(0, 8), S(64, 8), 1.0);
  Reset();
  glColor3b(-1, -64, 1);
  ExpectColor("glColor3b small", S(-1, 8), S(-64, 8), S(1, 8), 1.0);
}

TEST_F(CurrentAttribTest, ColorUnsignedShort) {
  const GLushort v[4] = {0, 65535, 32768, 1};
  glColor4us(v[0], v[1], v[2], v[3]);
  ExpectColor("glColor4us", 0.0, 1.0, U(32768, 16), U(1, 16));
  Reset();
  glColor4usv(v);
  ExpectColor("glColor4usv", 0.0, 1.0, U(32768, 16), U(1, 16));
  Reset();
  glColor3us(v[2], v[1], v[0]);
  ExpectColor("glColor3us", U(32768, 16), 1.0, 0.0, 1.0);
  Reset();
  glColor3usv(v + 1);
  ExpectColor("glColor3usv", 1.0, U(32768, 16), U(1, 16), 1.0);
}

TEST_F(CurrentAttribTest, ColorSignedShort) {
  const GLshort v[4] = {-32768, 32767, 0, 1000};
  glColor4s(v[0], v[1], v[2], v[3]);
  ExpectColor("glColor4s", -1.0, 1.0, S(0, 16), S(1000, 16));
  Reset();
  glColor4sv(v);
  ExpectColor("glColor4sv", -1.0, 1.0, S(0, 16), S(1000, 16));
  Reset();
  glColor3s(v[3], v[2], v[1]);
  ExpectColor("glColor3s", S(1000, 16), S(0, 16), 1.0, 1.0);
  Reset();
  glColor3sv(v);
  ExpectColor("glColor3sv", -1.0, 1.0, S(0, 16), 1.0);
}

TEST_F(CurrentAttribTest, ColorUnsignedInt) {
  const GLuint v[4] = {0u, 0xFFFFFFFFu, 0x80000000u, 0x40000000u};
  glColor4ui(v[0], v[1], v[2], v[3]);
  ExpectColor("glColor4ui", 0.0, 1.0, U(2147483648.0, 32), U(1073741824.0, 32));
  Reset();
  glColor4uiv(v);
  ExpectColor("glColor4uiv", 0.0, 1.0, U(2147483648.0, 32), U(1073741824.0, 32));
  Reset();
  glColor3ui(v[3], v[1], v[0]);
  ExpectColor("glColor3ui", U(1073741824.0, 32), 1.0, 0.0, 1.0);
  Reset();
  glColor3uiv(v + 1);
  ExpectColor("glColor3uiv", 1.0, U(2147483648.0, 32), U(1073741824.0, 32), 1.0);
}

TEST_F(CurrentAttribTest, ColorSignedInt) {
  const GLint v[4] = {INT_MIN, INT_MAX, 0, 1 << 29};
  glColor4i(v[0], v[1], v[2], v[3]);
  ExpectColor("glColor4i", -1.0, 1.0, S(0, 32), S(1 << 29, 32));
  Reset();
  glColor4iv(v);
  ExpectColor("glColor4iv", -1.0, 1.0, S(0, 32), S(1 << 29, 32));
  Reset();
  glColor3i(v[3], v[0], v[1]);
  ExpectColor("glColor3i", S(1 << 29, 32), -1.0, 1.0, 1.0);
  Reset();
  glColor3iv(v + 1);
  ExpectColor("glColor3iv", 1.0, S(0, 32), S(1 << 29, 32), 1.0);
}

TEST_F(CurrentAttribTest, ColorFloatAndDoubleAreNotClamped) {
  const GLfloat f[4] = {0.25f, -0.5f, 2.0f, 1.5f};
  glColor4f(f[0], f[1], f[2], f[3]);
  ExpectColor("glColor4f", 0.25, -0.5, 2.0, 1.5);
  Reset();
  glColor4fv(f);
  ExpectColor("glColor4fv", 0.25, -0.5, 2.0, 1.5);
  Reset();
  glColor3f(f[3], f[2], f[1]);
  ExpectColor("glColor3f", 1.5, 2.0, -0.5, 1.0);
  Reset();
  glColor3fv(f);
  ExpectColor("glColor3fv", 0.25, -0.5, 2.0, 1.0);
  const GLdouble d[4] = {0.125, 0.3, -3.0, 0.0};
  Reset();
  glColor4d(d[0], d[1], d[2], d[3]);
  ExpectColor("glColor4d", 0.125, 0.3, -3.0, 0.0);
  Reset();
  glColor4dv(d);
  ExpectColor("glColor4dv", 0.125, 0.3, -3.0, 0.0);
  Reset();
  glColor3d(d[1], d[0], d[2]);
  ExpectColor("glColor3d", 0.3, 0.125, -3.0, 1.0);
  Reset();
  glColor3dv(d);
  ExpectColor("glColor3dv", 0.125, 0.3, -3.0, 1.0);
}

TEST_F(CurrentAttribTest, NormalAllTypes) {
  const GLbyte b[3] = {-128, 127, 0};
  glNormal3b(b[0], b[1], b[2]);
  ExpectNormal("glNormal3b", -1.0, 1.0, S(0, 8));
  glNormal3f(9, 9, 9);
  glNormal3bv(b);
  ExpectNormal("glNormal3bv", -1.0, 1.0, S(0, 8));
  glNormal3b(10, -10, 1);
  ExpectNormal("glNormal3b small", S(10, 8), S(-10, 8), S(1, 8));

  const GLshort s[3] = {32767, -32768, 100};
  glNormal3s(s[0], s[1], s[2]);
  ExpectNormal("glNormal3s", 1.0, -1.0, S(100, 16));
  glNormal3f(9, 9, 9);
  glNormal3sv(s);
  ExpectNormal("glNormal3sv", 1.0, -1.0, S(100, 16));

  const GLint i[3] = {0, INT_MIN, INT_MAX};
  glNormal3i(i[0], i[1], i[2]);
  ExpectNormal("glNormal3i", S(0, 32), -1.0, 1.0);
  glNormal3f(9, 9, 9);
  glNormal3iv(i);
  ExpectNormal("glNormal3iv", S(0, 32), -1.0, 1.0);

  // Not normalised, as given.
  const GLfloat f[3] = {2.0f, -0.5f, 0.0f};
  glNormal3f(f[0], f[1], f[2]);
  ExpectNormal("glNormal3f", 2.0, -0.5, 0.0);
  glNormal3f(9, 9, 9);
  glNormal3fv(f);
  ExpectNormal("glNormal3fv", 2.0, -0.5, 0.0);

  const GLdouble d[3] = {0.1, 0.2, -7.0};
  glNormal3d(d[0], d[1], d[2]);
  ExpectNormal("glNormal3d", 0.1, 0.2, -7.0);
  glNormal3f(9, 9, 9);
  glNormal3dv(d);
  ExpectNormal("glNormal3dv", 0.1, 0.2, -7.0);
}

// §2.7: Color3 sets alpha to 1.0, whatever came before.
TEST_F(CurrentAttribTest, Color3AfterColor4SetsAlphaToOne) {
  GLFX_SKIP_ON_MESA("Mesa 22 bug (vbo): glColor4f(..., -9) then glColor3f leaves alpha -9 in some sequences");
  const GLfloat f[3] = {0.25f, -0.5f, 2.0f};
  for (int round = 0; round < 3; ++round) {
    glColor4f(-9, -9, -9, -9);
    glColor3f(1.5f, 2.0f, -0.5f);
    ExpectColor("glColor4f then glColor3f", 1.5, 2.0, -0.5, 1.0);
    glColor4f(-9, -9, -9, -9);
    glColor3fv(f);
    ExpectColor("glColor4f then glColor3fv", 0.25, -0.5, 2.0, 1.0);
    glColor4f(0, 0, 0, 0.5f);
    glColor3ub(255, 0, 0);
    ExpectColor("glColor4f then glColor3ub", 1.0, 0.0, 0.0, 1.0);
  }
}

TEST_F(CurrentAttribTest, ColorAndNormalAreIndependent) {
  glColor3f(0.5f, 0.25f, 0.125f);
  glNormal3f(1, 0, 0);
  ExpectColor("colour", 0.5, 0.25, 0.125, 1.0);
  ExpectNormal("normal", 1.0, 0.0, 0.0);
  glColor4f(0, 0, 0, 0);
  ExpectNormal("normal after glColor", 1.0, 0.0, 0.0);
}

// GetIntegerv of the current colour maps [-1,1] onto the integers (§6.1.2).
TEST_F(CurrentAttribTest, IntegerQueryOfTheCurrentColor) {
  glColor4ub(255, 0, 255, 0);
  std::array<GLint, 4> c = GetInts<4>(GL_CURRENT_COLOR);
  EXPECT_NEAR(c[0], INT_MAX, 1);
  EXPECT_NEAR(c[1], 0, 1);
  EXPECT_NEAR(c[2], INT_MAX, 1);
  EXPECT_NEAR(c[3], 0, 1);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
