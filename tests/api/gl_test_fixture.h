// A GoogleTest fixture for the GL API tests: one OSMesa context per test,
// RGBA, 24-bit depth, no stencil or accumulation buffer, bound to a malloc'd
// 64x64 client buffer; plus small query and matrix helpers.
//
// The tests compile against the project's headers (include/GL) and against
// Mesa's system headers, so that they can be run on Mesa's OSMesa as well.
// Build with -DTESTING_AGAINST_MESA to run them on Mesa: the few checks where
// Mesa (a GL 4.5 compatibility context) knowingly differs from GL 2.1 are then
// skipped, each with the reason (GLFX_SKIP_ON_MESA, kTestingAgainstMesa).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1  // Mesa's gl.h: declare glProvokingVertex
#endif
#include <GL/gl.h>
#include <GL/osmesa.h>
#if !defined(GL_PROVOKING_VERTEX) || !defined(GL_LAST_VERTEX_CONVENTION)
#include <GL/glext.h>  // only a header without GL_ARB_provoking_vertex
#endif

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#ifdef TESTING_AGAINST_MESA
#define GLFX_SKIP_ON_MESA(why) GTEST_SKIP() << "Mesa differs from GL 2.1 here: " << why
#else
#define GLFX_SKIP_ON_MESA(why) \
  do {                         \
  } while (0)
#endif

// Checks the error flag (GL 2.1 §2.5) and clears it.
#define EXPECT_GL_ERROR(err) EXPECT_EQ(glGetError(), static_cast<GLenum>(err))
#define EXPECT_NO_GL_ERROR() EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR))
#define ASSERT_NO_GL_ERROR() ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR))

namespace glfx_test {

#ifdef TESTING_AGAINST_MESA
constexpr bool kTestingAgainstMesa = true;
#else
constexpr bool kTestingAgainstMesa = false;
#endif

constexpr int kWidth = 64;
constexpr int kHeight = 64;

// Reads every pending error (an implementation may keep several flags);
// returns the first one.
inline GLenum DrainErrors() {
  GLenum first = glGetError();
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
  return first;
}

// An OSMesa context and its client colour buffer, released on destruction.
class ScopedContext {
 public:
  ScopedContext(GLenum format, GLint depthBits, int width, int height, int bytesPerPixel)
      : width_(width), height_(height) {
    ctx_ = OSMesaCreateContextExt(format, depthBits, 0, 0, NULL);
    buffer_ = std::malloc(static_cast<size_t>(width) * height * bytesPerPixel);
    if (buffer_) std::memset(buffer_, 0xA5, static_cast<size_t>(width) * height * bytesPerPixel);
  }
  ~ScopedContext() {
    if (ctx_) {
      if (OSMesaGetCurrentContext() == ctx_) OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
      OSMesaDestroyContext(ctx_);
    }
    std::free(buffer_);
  }
  ScopedContext(const ScopedContext&) = delete;
  ScopedContext& operator=(const ScopedContext&) = delete;

  bool makeCurrent() {
    return ctx_ && buffer_ && OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, width_, height_) == GL_TRUE;
  }
  OSMesaContext get() const { return ctx_; }
  unsigned char* bytes() const { return static_cast<unsigned char*>(buffer_); }

 private:
  OSMesaContext ctx_ = nullptr;
  void* buffer_ = nullptr;
  int width_, height_;
};

class GLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    ASSERT_NE(ctx_, nullptr) << "OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL) failed";
    buffer_ = std::malloc(kWidth * kHeight * 4);
    ASSERT_NE(buffer_, nullptr);
    std::memset(buffer_, 0xA5, kWidth * kHeight * 4);
    ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "a fresh context has an error set";
  }

  void TearDown() override {
    if (ctx_) {
      // Leave the call-with-no-context path, not a dangling context, behind.
      if (OSMesaGetCurrentContext() == ctx_) OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
      OSMesaDestroyContext(ctx_);
      ctx_ = nullptr;
    }
    std::free(buffer_);
    buffer_ = nullptr;
  }

  // The client colour buffer, after glFinish: OSMesa need not have written
  // the rendering into client memory before then (Mesa's gallium OSMesa
  // copies it there at glFinish/glFlush).
  unsigned char* pixels() const {
    glFinish();
    return static_cast<unsigned char*>(buffer_);
  }

  OSMesaContext ctx_ = nullptr;
  void* buffer_ = nullptr;
};

// ---- queries ------------------------------------------------------------------

inline GLint GetInt(GLenum pname) {
  GLint v[16];
  for (GLint& x : v) x = -12345;
  glGetIntegerv(pname, v);
  return v[0];
}
inline GLfloat GetFloat(GLenum pname) {
  GLfloat v[16];
  for (GLfloat& x : v) x = -12345.0f;
  glGetFloatv(pname, v);
  return v[0];
}
inline GLdouble GetDouble(GLenum pname) {
  GLdouble v[16];
  for (GLdouble& x : v) x = -12345.0;
  glGetDoublev(pname, v);
  return v[0];
}
inline GLboolean GetBool(GLenum pname) {
  GLboolean v[16];
  for (GLboolean& x : v) x = 77;
  glGetBooleanv(pname, v);
  return v[0];
}
template <int N>
std::array<GLint, N> GetInts(GLenum pname) {
  GLint v[16];
  for (GLint& x : v) x = -12345;
  glGetIntegerv(pname, v);
  std::array<GLint, N> r;
  for (int i = 0; i < N; ++i) r[i] = v[i];
  return r;
}
template <int N>
std::array<GLfloat, N> GetFloats(GLenum pname) {
  GLfloat v[16];
  for (GLfloat& x : v) x = -12345.0f;
  glGetFloatv(pname, v);
  std::array<GLfloat, N> r;
  for (int i = 0; i < N; ++i) r[i] = v[i];
  return r;
}
template <int N>
std::array<GLdouble, N> GetDoubles(GLenum pname) {
  GLdouble v[16];
  for (GLdouble& x : v) x = -12345.0;
  glGetDoublev(pname, v);
  std::array<GLdouble, N> r;
  for (int i = 0; i < N; ++i) r[i] = v[i];
  return r;
}
template <int N>
std::array<GLboolean, N> GetBools(GLenum pname) {
  GLboolean v[16];
  for (GLboolean& x : v) x = 77;
  glGetBooleanv(pname, v);
  std::array<GLboolean, N> r;
  for (int i = 0; i < N; ++i) r[i] = v[i];
  return r;
}

// GL 2.1 §6.1.2: GetIntegerv of a colour component, depth range, depth clear
// value or normal coordinate f in [-1,1] maps f linearly: 1.0 to the most
// positive and -1.0 to the most negative integer (the INT row of table 2.9
// read backwards, c = ((2^32-1) f - 1) / 2). Mesa truncates 2147483647 f. Both
// agree to within 1; this is the value a test accepts within 1.
inline double NormalizedToInt(double f) { return 2147483647.0 * f; }

// ---- double-precision matrices, column-major as GL stores them ----------------

struct Mat4 {
  double m[16];  // m[col * 4 + row]
  double& at(int row, int col) { return m[col * 4 + row]; }
  double at(int row, int col) const { return m[col * 4 + row]; }
};

inline Mat4 Identity() {
  Mat4 r{};
  for (int i = 0; i < 4; ++i) r.at(i, i) = 1.0;
  return r;
}
inline Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.at(row, k) * b.at(k, col);
      r.at(row, col) = s;
    }
  return r;
}
inline Mat4 FromColumnMajor(const double* v) {
  Mat4 r;
  for (int i = 0; i < 16; ++i) r.m[i] = v[i];
  return r;
}
inline Mat4 FromColumnMajor(const float* v) {
  Mat4 r;
  for (int i = 0; i < 16; ++i) r.m[i] = v[i];
  return r;
}
// GL 2.1 §2.11.2, equation for Translate.
inline Mat4 TranslationRef(double x, double y, double z) {
  Mat4 r = Identity();
  r.at(0, 3) = x;
  r.at(1, 3) = y;
  r.at(2, 3) = z;
  return r;
}
inline Mat4 ScaleRef(double x, double y, double z) {
  Mat4 r = Identity();
  r.at(0, 0) = x;
  r.at(1, 1) = y;
  r.at(2, 2) = z;
  return r;
}
// GL 2.1 §2.11.2: u = (x y z)/|(x y z)|, S = [0 -z y; z 0 -x; -y x 0],
// R = u u^T + cos(theta) (I - u u^T) + sin(theta) S, theta in degrees.
inline Mat4 RotationRef(double angleDegrees, double x, double y, double z) {
  double len = std::sqrt(x * x + y * y + z * z);
  double u[3] = {x / len, y / len, z / len};
  double th = angleDegrees * 3.14159265358979323846 / 180.0;
  double c = std::cos(th), s = std::sin(th);
  double S[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
  Mat4 r = Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double uu = u[i] * u[j];
      r.at(i, j) = uu + c * ((i == j ? 1.0 : 0.0) - uu) + s * S[i][j];
    }
  return r;
}
// GL 2.1 §2.11.2, Frustum.
inline Mat4 FrustumRef(double l, double r, double b, double t, double n, double f) {
  Mat4 m{};
  m.at(0, 0) = 2 * n / (r - l);
  m.at(0, 2) = (r + l) / (r - l);
  m.at(1, 1) = 2 * n / (t - b);
  m.at(1, 2) = (t + b) / (t - b);
  m.at(2, 2) = -(f + n) / (f - n);
  m.at(2, 3) = -2 * f * n / (f - n);
  m.at(3, 2) = -1;
  return m;
}
// GL 2.1 §2.11.2, Ortho.
inline Mat4 OrthoRef(double l, double r, double b, double t, double n, double f) {
  Mat4 m = Identity();
  m.at(0, 0) = 2 / (r - l);
  m.at(0, 3) = -(r + l) / (r - l);
  m.at(1, 1) = 2 / (t - b);
  m.at(1, 3) = -(t + b) / (t - b);
  m.at(2, 2) = -2 / (f - n);
  m.at(2, 3) = -(f + n) / (f - n);
  return m;
}

// Compares the matrix `pname` (GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX), read
// with both glGetDoublev and glGetFloatv, with `expected`. The library computes
// in single precision, so the tolerance is relative to float.
inline ::testing::AssertionResult MatrixIs(GLenum pname, const Mat4& expected, double relTol = 2e-6) {
  GLdouble d[16];
  GLfloat f[16];
  for (int i = 0; i < 16; ++i) {
    d[i] = -999.0;
    f[i] = -999.0f;
  }
  glGetDoublev(pname, d);
  glGetFloatv(pname, f);
  double scale = 1.0;
  for (double v : expected.m) scale = std::fmax(scale, std::fabs(v));
  for (int i = 0; i < 16; ++i) {
    double tol = relTol * scale;
    if (std::fabs(d[i] - expected.m[i]) > tol || std::fabs(f[i] - expected.m[i]) > tol) {
      ::testing::AssertionResult r = ::testing::AssertionFailure();
      r << "element " << i << " (row " << i % 4 << ", column " << i / 4 << "): expected " << expected.m[i]
        << ", glGetDoublev gave " << d[i] << ", glGetFloatv gave " << f[i] << "\n  whole matrix (double):";
      for (int k = 0; k < 16; ++k) r << " " << d[k];
      return r;
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace glfx_test
