// Initial state (GL 2.1 §6.2, tables 6.4 to 6.42), setting it and reading it
// back through every query, and the conversions of §6.1.2 between the type of
// a piece of state and the type a query returns.
#include <climits>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using StateQueryTest = GLTest;

// How GetIntegerv converts a piece of state (§6.1.2).
enum class Kind {
  kInteger,     // integer or enum state: returned as is by every query
  kBoolean,     // boolean state: 0/1 as a number
  kFloat,       // floating-point state: GetIntegerv rounds to nearest
  kNormalized,  // colour, depth range, depth clear value, normal: GetIntegerv maps [-1,1]
  kMatrix,      // a matrix: floating-point state, GetIntegerv rounds to nearest
};

struct Expected {
  const char* name;
  GLenum pname;
  Kind kind;
  int count;
  double value[16];
};

// Checks `e` through GetBooleanv, GetIntegerv, GetFloatv and GetDoublev, and,
// for a boolean, glIsEnabled.
void ExpectState(const Expected& e) {
  SCOPED_TRACE(e.name);
  GLboolean b[17];
  GLint i[17];
  GLfloat f[17];
  GLdouble d[17];
  for (int k = 0; k < 17; ++k) {
    b[k] = 77;
    i[k] = -12345;
    f[k] = -12345.0f;
    d[k] = -12345.0;
  }
  glGetBooleanv(e.pname, b);
  glGetIntegerv(e.pname, i);
  glGetFloatv(e.pname, f);
  glGetDoublev(e.pname, d);
  for (int k = 0; k < e.count; ++k) {
    SCOPED_TRACE(::testing::Message() << "component " << k);
    double v = e.value[k];
    EXPECT_EQ(b[k], v != 0.0 ? GL_TRUE : GL_FALSE) << "glGetBooleanv";
    EXPECT_NEAR(d[k], v, 1e-6 * std::fmax(1.0, std::fabs(v))) << "glGetDoublev";
    EXPECT_NEAR(f[k], v, 1e-6 * std::fmax(1.0, std::fabs(v))) << "glGetFloatv";
    switch (e.kind) {
      case Kind::kInteger:
      case Kind::kBoolean:
        EXPECT_EQ(i[k], static_cast<GLint>(v)) << "glGetIntegerv";
        EXPECT_EQ(d[k], v) << "glGetDoublev of integer state is exact";
        EXPECT_EQ(f[k], static_cast<float>(v)) << "glGetFloatv of integer state is exact";
        break;
      case Kind::kFloat:
        EXPECT_EQ(i[k], static_cast<GLint>(std::lround(v))) << "glGetIntegerv rounds to nearest";
        break;
      case Kind::kMatrix:
        // Mesa (get.c, TYPE_MATRIX) maps matrix elements like colours, 1.0 to
        // 2^31-1; §6.1.2 rounds them (IntegerQueryOfMatrixRoundsToNearest).
        if (!kTestingAgainstMesa) {
          EXPECT_EQ(i[k], static_cast<GLint>(std::lround(v))) << "glGetIntegerv rounds to nearest";
        }
        break;
      case Kind::kNormalized:
        EXPECT_NEAR(static_cast<double>(i[k]), NormalizedToInt(v), 1.0) << "glGetIntegerv maps [-1,1]";
        break;
    }
  }
  // Nothing is written past the state's size.
  EXPECT_EQ(b[e.count], 77);
  EXPECT_EQ(i[e.count], -12345);
  EXPECT_EQ(f[e.count], -12345.0f);
  EXPECT_EQ(d[e.count], -12345.0);
  if (e.kind == Kind::kBoolean) {
    EXPECT_EQ(glIsEnabled(e.pname), e.value[0] != 0.0 ? GL_TRUE : GL_FALSE) << "glIsEnabled";
  }
  EXPECT_NO_GL_ERROR();
}

#define ID16 \
  { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 }

TEST_F(StateQueryTest, InitialStateTable) {
  const Expected table[] = {
      {"GL_MATRIX_MODE", GL_MATRIX_MODE, Kind::kInteger, 1, {GL_MODELVIEW}},
      {"GL_MODELVIEW_MATRIX", GL_MODELVIEW_MATRIX, Kind::kMatrix, 16, ID16},
      {"GL_PROJECTION_MATRIX", GL_PROJECTION_MATRIX, Kind::kMatrix, 16, ID16},
      {"GL_MODELVIEW_STACK_DEPTH", GL_MODELVIEW_STACK_DEPTH, Kind::kInteger, 1, {1}},
      {"GL_PROJECTION_STACK_DEPTH", GL_PROJECTION_STACK_DEPTH, Kind::kInteger, 1, {1}},
      {"GL_MAX_MODELVIEW_STACK_DEPTH", GL_MAX_MODELVIEW_STACK_DEPTH, Kind::kInteger, 1, {32}},
      {"GL_MAX_PROJECTION_STACK_DEPTH", GL_MAX_PROJECTION_STACK_DEPTH, Kind::kInteger, 1, {32}},
      {"GL_VIEWPORT", GL_VIEWPORT, Kind::kInteger, 4, {0, 0, kWidth, kHeight}},
      {"GL_DEPTH_RANGE", GL_DEPTH_RANGE, Kind::kNormalized, 2, {0, 1}},
      {"GL_COLOR_CLEAR_VALUE", GL_COLOR_CLEAR_VALUE, Kind::kNormalized, 4, {0, 0, 0, 0}},
      {"GL_DEPTH_CLEAR_VALUE", GL_DEPTH_CLEAR_VALUE, Kind::kNormalized, 1, {1}},
      {"GL_DEPTH_FUNC", GL_DEPTH_FUNC, Kind::kInteger, 1, {GL_LESS}},
      {"GL_DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, Kind::kInteger, 1, {GL_TRUE}},
      {"GL_DEPTH_TEST", GL_DEPTH_TEST, Kind::kBoolean, 1, {0}},
      {"GL_CULL_FACE", GL_CULL_FACE, Kind::kBoolean, 1, {0}},
      {"GL_CULL_FACE_MODE", GL_CULL_FACE_MODE, Kind::kInteger, 1, {GL_BACK}},
      {"GL_FRONT_FACE", GL_FRONT_FACE, Kind::kInteger, 1, {GL_CCW}},
      {"GL_SHADE_MODEL", GL_SHADE_MODEL, Kind::kInteger, 1, {GL_SMOOTH}},
      {"GL_CURRENT_COLOR", GL_CURRENT_COLOR, Kind::kNormalized, 4, {1, 1, 1, 1}},
      {"GL_CURRENT_NORMAL", GL_CURRENT_NORMAL, Kind::kNormalized, 3, {0, 0, 1}},
      {"GL_DITHER", GL_DITHER, Kind::kBoolean, 1, {1}},
      {"GL_NORMALIZE", GL_NORMALIZE, Kind::kBoolean, 1, {0}},
      {"GL_RESCALE_NORMAL", GL_RESCALE_NORMAL, Kind::kBoolean, 1, {0}},
      {"GL_LIGHTING", GL_LIGHTING, Kind::kBoolean, 1, {0}},
      {"GL_COLOR_MATERIAL", GL_COLOR_MATERIAL, Kind::kBoolean, 1, {0}},
      {"GL_SUBPIXEL_BITS", GL_SUBPIXEL_BITS, Kind::kInteger, 1, {8}},
      {"GL_DEPTH_BITS", GL_DEPTH_BITS, Kind::kInteger, 1, {24}},
      {"GL_RED_BITS", GL_RED_BITS, Kind::kInteger, 1, {8}},
      {"GL_GREEN_BITS", GL_GREEN_BITS, Kind::kInteger, 1, {8}},
      {"GL_BLUE_BITS", GL_BLUE_BITS, Kind::kInteger, 1, {8}},
      {"GL_ALPHA_BITS", GL_ALPHA_BITS, Kind::kInteger, 1, {8}},
      {"GL_PROVOKING_VERTEX", GL_PROVOKING_VERTEX, Kind::kInteger, 1, {GL_LAST_VERTEX_CONVENTION}},
      {"GL_MAX_LIGHTS", GL_MAX_LIGHTS, Kind::kInteger, 1, {8}},
      {"GL_LIGHT0", GL_LIGHT0, Kind::kBoolean, 1, {0}},
      {"GL_LIGHT7", GL_LIGHT7, Kind::kBoolean, 1, {0}},
  };
  for (const Expected& e : table) ExpectState(e);
}

TEST_F(StateQueryTest, MaxViewportDimsCoverTheBuffer) {
  std::array<GLint, 2> dims = GetInts<2>(GL_MAX_VIEWPORT_DIMS);
  EXPECT_GE(dims[0], kWidth);
  EXPECT_GE(dims[1], kHeight);
  std::array<GLfloat, 2> fdims = GetFloats<2>(GL_MAX_VIEWPORT_DIMS);
  EXPECT_EQ(fdims[0], static_cast<float>(dims[0]));
  EXPECT_EQ(fdims[1], static_cast<float>(dims[1]));
  std::array<GLboolean, 2> bdims = GetBools<2>(GL_MAX_VIEWPORT_DIMS);
  EXPECT_EQ(bdims[0], GL_TRUE);
  EXPECT_EQ(bdims[1], GL_TRUE);
  EXPECT_NO_GL_ERROR();
}

// ---- set, then read back ---------------------------------------------------------

TEST_F(StateQueryTest, MatrixModeRoundTrip) {
  glMatrixMode(GL_PROJECTION);
  ExpectState({"projection", GL_MATRIX_MODE, Kind::kInteger, 1, {GL_PROJECTION}});
  glMatrixMode(GL_MODELVIEW);
  ExpectState({"modelview", GL_MATRIX_MODE, Kind::kInteger, 1, {GL_MODELVIEW}});
}

// §5.6: every hint starts GL_DONT_CARE and reads back what was set.
TEST_F(StateQueryTest, HintsRoundTrip) {
  const GLenum targets[] = {GL_PERSPECTIVE_CORRECTION_HINT,
                            GL_POINT_SMOOTH_HINT,
                            GL_LINE_SMOOTH_HINT,
                            GL_POLYGON_SMOOTH_HINT,
                            GL_FOG_HINT,
                            GL_GENERATE_MIPMAP_HINT,
                            GL_TEXTURE_COMPRESSION_HINT,
                            GL_FRAGMENT_SHADER_DERIVATIVE_HINT};
  for (GLenum t : targets) {
    ExpectState({"default", t, Kind::kInteger, 1, {GL_DONT_CARE}});
    glHint(t, GL_NICEST);
    ExpectState({"nicest", t, Kind::kInteger, 1, {GL_NICEST}});
    glHint(t, GL_FASTEST);
    ExpectState({"fastest", t, Kind::kInteger, 1, {GL_FASTEST}});
  }
  glHint(GL_FOG_HINT, GL_FOG);  // not a hint mode
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  ExpectState({"unchanged", GL_FOG_HINT, Kind::kInteger, 1, {GL_FASTEST}});
}

TEST_F(StateQueryTest, ViewportRoundTrip) {
  glViewport(3, 5, 40, 20);
  ExpectState({"viewport", GL_VIEWPORT, Kind::kInteger, 4, {3, 5, 40, 20}});
  glViewport(-10, -20, 30, 7);  // any origin is allowed
  ExpectState({"negative origin", GL_VIEWPORT, Kind::kInteger, 4, {-10, -20, 30, 7}});
  glViewport(0, 0, 0, 0);  // zero size is allowed
  ExpectState({"empty", GL_VIEWPORT, Kind::kInteger, 4, {0, 0, 0, 0}});
}

// §2.11.1: a too large viewport is silently clamped to GL_MAX_VIEWPORT_DIMS.
TEST_F(StateQueryTest, ViewportIsClampedToMaxViewportDims) {
  std::array<GLint, 2> dims = GetInts<2>(GL_MAX_VIEWPORT_DIMS);
  glViewport(1, 2, 1 << 30, 1 << 30);
  EXPECT_NO_GL_ERROR();
  std::array<GLint, 4> v = GetInts<4>(GL_VIEWPORT);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[1], 2);
  EXPECT_EQ(v[2], dims[0]);
  EXPECT_EQ(v[3], dims[1]);
}

TEST_F(StateQueryTest, DepthRangeRoundTripAndClamp) {
  glDepthRange(0.25, 0.75);
  ExpectState({"depth range", GL_DEPTH_RANGE, Kind::kNormalized, 2, {0.25, 0.75}});
  glDepthRange(1.0, 0.0);  // reversed is allowed
  ExpectState({"reversed", GL_DEPTH_RANGE, Kind::kNormalized, 2, {1.0, 0.0}});
  glDepthRange(-1.0, 2.0);  // §2.11.1: clamped to [0,1]
  ExpectState({"clamped", GL_DEPTH_RANGE, Kind::kNormalized, 2, {0.0, 1.0}});
}

TEST_F(StateQueryTest, ClearColorRoundTripAndClamp) {
  glClearColor(0.125f, 0.25f, 0.5f, 0.75f);
  ExpectState({"clear colour", GL_COLOR_CLEAR_VALUE, Kind::kNormalized, 4, {0.125, 0.25, 0.5, 0.75}});
  glClearColor(-1.0f, 2.0f, 0.5f, 3.0f);  // §4.2.3: clamped to [0,1]
  ExpectState({"clamped", GL_COLOR_CLEAR_VALUE, Kind::kNormalized, 4, {0.0, 1.0, 0.5, 1.0}});
}

TEST_F(StateQueryTest, ClearDepthRoundTripAndClamp) {
  glClearDepth(0.5);
  ExpectState({"clear depth", GL_DEPTH_CLEAR_VALUE, Kind::kNormalized, 1, {0.5}});
  glClearDepth(2.0);  // §4.2.3: clamped to [0,1]
  ExpectState({"clamped high", GL_DEPTH_CLEAR_VALUE, Kind::kNormalized, 1, {1.0}});
  glClearDepth(-3.0);
  ExpectState({"clamped low", GL_DEPTH_CLEAR_VALUE, Kind::kNormalized, 1, {0.0}});
}

TEST_F(StateQueryTest, DepthFuncRoundTrip) {
  const GLenum funcs[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                          GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  for (GLenum f : funcs) {
    glDepthFunc(f);
    ExpectState({"depth func", GL_DEPTH_FUNC, Kind::kInteger, 1, {static_cast<double>(f)}});
  }
}

TEST_F(StateQueryTest, DepthMaskRoundTrip) {
  glDepthMask(GL_FALSE);
  ExpectState({"false", GL_DEPTH_WRITEMASK, Kind::kInteger, 1, {GL_FALSE}});
  glDepthMask(GL_TRUE);
  ExpectState({"true", GL_DEPTH_WRITEMASK, Kind::kInteger, 1, {GL_TRUE}});
}

TEST_F(StateQueryTest, EnableDisableRoundTrip) {
  const struct {
    const char* name;
    GLenum cap;
    bool initial;
  } caps[] = {
      {"GL_DEPTH_TEST", GL_DEPTH_TEST, false},
      {"GL_CULL_FACE", GL_CULL_FACE, false},
      {"GL_DITHER", GL_DITHER, true},
      {"GL_NORMALIZE", GL_NORMALIZE, false},
      {"GL_RESCALE_NORMAL", GL_RESCALE_NORMAL, false},
      {"GL_LIGHTING", GL_LIGHTING, false},
      {"GL_COLOR_MATERIAL", GL_COLOR_MATERIAL, false},
      {"GL_LIGHT0", GL_LIGHT0, false},
      {"GL_LIGHT3", GL_LIGHT3, false},
      {"GL_LIGHT7", GL_LIGHT7, false},
  };
  for (const auto& c : caps) {
    glEnable(c.cap);
    ExpectState({c.name, c.cap, Kind::kBoolean, 1, {1}});
    glDisable(c.cap);
    ExpectState({c.name, c.cap, Kind::kBoolean, 1, {0}});
    glEnable(c.cap);
    glEnable(c.cap);  // enabling twice is harmless
    ExpectState({c.name, c.cap, Kind::kBoolean, 1, {1}});
    if (!c.initial) glDisable(c.cap);
  }
  // One cap does not touch another.
  glEnable(GL_LIGHTING);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_LIGHT0), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_COLOR_MATERIAL), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(StateQueryTest, CullFaceFrontFaceShadeModelRoundTrip) {
  for (GLenum mode : {GL_FRONT, GL_FRONT_AND_BACK, GL_BACK}) {
    glCullFace(mode);
    ExpectState({"cull face mode", GL_CULL_FACE_MODE, Kind::kInteger, 1, {static_cast<double>(mode)}});
  }
  glFrontFace(GL_CW);
  ExpectState({"cw", GL_FRONT_FACE, Kind::kInteger, 1, {GL_CW}});
  glFrontFace(GL_CCW);
  ExpectState({"ccw", GL_FRONT_FACE, Kind::kInteger, 1, {GL_CCW}});
  glShadeModel(GL_FLAT);
  ExpectState({"flat", GL_SHADE_MODEL, Kind::kInteger, 1, {GL_FLAT}});
  glShadeModel(GL_SMOOTH);
  ExpectState({"smooth", GL_SHADE_MODEL, Kind::kInteger, 1, {GL_SMOOTH}});
}

TEST_F(StateQueryTest, ProvokingVertexRoundTrip) {
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  ExpectState({"first", GL_PROVOKING_VERTEX, Kind::kInteger, 1, {GL_FIRST_VERTEX_CONVENTION}});
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  ExpectState({"last", GL_PROVOKING_VERTEX, Kind::kInteger, 1, {GL_LAST_VERTEX_CONVENTION}});
}

TEST_F(StateQueryTest, CurrentColorAndNormalRoundTrip) {
  glColor4f(0.25f, 0.5f, 0.75f, 0.125f);
  ExpectState({"colour", GL_CURRENT_COLOR, Kind::kNormalized, 4, {0.25, 0.5, 0.75, 0.125}});
  glNormal3f(0.0f, -1.0f, 0.5f);
  ExpectState({"normal", GL_CURRENT_NORMAL, Kind::kNormalized, 3, {0.0, -1.0, 0.5}});
}

// ---- §6.1.2 conversions -----------------------------------------------------------

TEST_F(StateQueryTest, BooleanQueryOfNumbersIsNonZero) {
  glClearColor(0.5f, 0.0f, 1.0f, 0.0f);
  std::array<GLboolean, 4> b = GetBools<4>(GL_COLOR_CLEAR_VALUE);
  EXPECT_EQ(b[0], GL_TRUE);
  EXPECT_EQ(b[1], GL_FALSE);
  EXPECT_EQ(b[2], GL_TRUE);
  EXPECT_EQ(b[3], GL_FALSE);
  glViewport(0, 7, 0, 9);
  std::array<GLboolean, 4> vb = GetBools<4>(GL_VIEWPORT);
  EXPECT_EQ(vb[0], GL_FALSE);
  EXPECT_EQ(vb[1], GL_TRUE);
  EXPECT_EQ(vb[2], GL_FALSE);
  EXPECT_EQ(vb[3], GL_TRUE);
  EXPECT_EQ(GetBool(GL_MATRIX_MODE), GL_TRUE);  // an enum is non-zero
  EXPECT_EQ(GetBool(GL_MAX_LIGHTS), GL_TRUE);
  glClearDepth(0.0);
  EXPECT_EQ(GetBool(GL_DEPTH_CLEAR_VALUE), GL_FALSE);
  glClearDepth(0.001);
  EXPECT_EQ(GetBool(GL_DEPTH_CLEAR_VALUE), GL_TRUE);  // small, but not zero
  EXPECT_NO_GL_ERROR();
}

TEST_F(StateQueryTest, NumericQueryOfBooleans) {
  glEnable(GL_CULL_FACE);
  EXPECT_EQ(GetInt(GL_CULL_FACE), 1);
  EXPECT_EQ(GetFloat(GL_CULL_FACE), 1.0f);
  EXPECT_EQ(GetDouble(GL_CULL_FACE), 1.0);
  EXPECT_EQ(GetBool(GL_CULL_FACE), GL_TRUE);
  EXPECT_EQ(GetInt(GL_LIGHTING), 0);
  EXPECT_EQ(GetFloat(GL_LIGHTING), 0.0f);
  EXPECT_EQ(GetDouble(GL_LIGHTING), 0.0);
  glDepthMask(GL_FALSE);
  EXPECT_EQ(GetInt(GL_DEPTH_WRITEMASK), 0);
  EXPECT_EQ(GetFloat(GL_DEPTH_WRITEMASK), 0.0f);
  EXPECT_NO_GL_ERROR();
}

// §6.1.2: only colours, depth range, depth clear value and normals are
// mapped; any other floating-point state, matrices included, is rounded.
TEST_F(StateQueryTest, IntegerQueryOfMatrixRoundsToNearest) {
  GLFX_SKIP_ON_MESA("Mesa bug: glGetIntegerv maps matrix elements like colours (1.0 gives 2147483647)");
  glTranslatef(2.6f, -2.6f, 0.4f);
  glScalef(1.4f, -7.7f, 0.49f);
  std::array<GLint, 16> m = GetInts<16>(GL_MODELVIEW_MATRIX);
  const GLint expected[16] = {1, 0, 0, 0, 0, -8, 0, 0, 0, 0, 0, 0, 3, -3, 0, 1};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(m[i], expected[i]) << "element " << i;
  EXPECT_NO_GL_ERROR();
}

TEST_F(StateQueryTest, IntegerQueryOfColorsMapsTheUnitRange) {
  glClearColor(1.0f, 0.0f, 0.5f, 0.25f);
  std::array<GLint, 4> c = GetInts<4>(GL_COLOR_CLEAR_VALUE);
  EXPECT_NEAR(c[0], INT_MAX, 1);
  EXPECT_NEAR(c[1], 0, 1);
  EXPECT_NEAR(c[2], NormalizedToInt(0.5), 1.0);
  EXPECT_NEAR(c[3], NormalizedToInt(0.25), 1.0);
  glColor4f(1.0f, -1.0f, 0.0f, 0.75f);
  std::array<GLint, 4> cc = GetInts<4>(GL_CURRENT_COLOR);
  EXPECT_NEAR(cc[0], INT_MAX, 1);
  EXPECT_NEAR(static_cast<double>(cc[1]), static_cast<double>(INT_MIN), 1.0);
  EXPECT_NEAR(cc[2], 0, 1);
  EXPECT_NEAR(cc[3], NormalizedToInt(0.75), 1.0);
  glNormal3f(-1.0f, 1.0f, 0.5f);
  std::array<GLint, 3> n = GetInts<3>(GL_CURRENT_NORMAL);
  EXPECT_NEAR(static_cast<double>(n[0]), static_cast<double>(INT_MIN), 1.0);
  EXPECT_NEAR(n[1], INT_MAX, 1);
  EXPECT_NEAR(n[2], NormalizedToInt(0.5), 1.0);
  glDepthRange(0.5, 1.0);
  std::array<GLint, 2> dr = GetInts<2>(GL_DEPTH_RANGE);
  EXPECT_NEAR(dr[0], NormalizedToInt(0.5), 1.0);
  EXPECT_NEAR(dr[1], INT_MAX, 1);
  glClearDepth(1.0);
  EXPECT_NEAR(GetInt(GL_DEPTH_CLEAR_VALUE), INT_MAX, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(StateQueryTest, FloatAndDoubleQueriesOfEnums) {
  glDepthFunc(GL_GEQUAL);
  EXPECT_EQ(GetFloat(GL_DEPTH_FUNC), static_cast<float>(GL_GEQUAL));
  EXPECT_EQ(GetDouble(GL_DEPTH_FUNC), static_cast<double>(GL_GEQUAL));
  glMatrixMode(GL_PROJECTION);
  EXPECT_EQ(GetFloat(GL_MATRIX_MODE), static_cast<float>(GL_PROJECTION));
  EXPECT_EQ(GetDouble(GL_MATRIX_MODE), static_cast<double>(GL_PROJECTION));
  EXPECT_NO_GL_ERROR();
}

// ---- the viewport belongs to the first MakeCurrent ----------------------------------

TEST_F(StateQueryTest, NewContextViewportIsItsFirstBufferSize) {
  ScopedContext other(OSMESA_RGBA, 24, 32, 16, 4);
  ASSERT_TRUE(other.makeCurrent());
  std::array<GLint, 4> v = GetInts<4>(GL_VIEWPORT);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 0);
  EXPECT_EQ(v[2], 32);
  EXPECT_EQ(v[3], 16);
  EXPECT_NO_GL_ERROR();
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
}

// §2.11.1: the viewport is set "when a GL context is first attached to a
// window"; binding the same context again, even to another size, keeps it.
TEST_F(StateQueryTest, ViewportIsNotResetByALaterMakeCurrent) {
  glViewport(1, 2, 3, 4);
  std::vector<unsigned char> small(32 * 16 * 4);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, small.data(), GL_UNSIGNED_BYTE, 32, 16), GL_TRUE);
  std::array<GLint, 4> v = GetInts<4>(GL_VIEWPORT);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[1], 2);
  EXPECT_EQ(v[2], 3);
  EXPECT_EQ(v[3], 4);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  v = GetInts<4>(GL_VIEWPORT);
  EXPECT_EQ(v[2], 3);
  EXPECT_EQ(v[3], 4);
  EXPECT_NO_GL_ERROR();
}

TEST_F(StateQueryTest, ContextsKeepSeparateState) {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glMatrixMode(GL_PROJECTION);
  glEnable(0xFFFF);  // an error in this context
  {
    ScopedContext other(OSMESA_RGBA, 24, 16, 16, 4);
    ASSERT_TRUE(other.makeCurrent());
    EXPECT_NO_GL_ERROR() << "the error flag is per context";
    EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
    EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_MODELVIEW);
    EXPECT_EQ(GetFloat(GL_COLOR_CLEAR_VALUE), 0.0f);
    glDisable(GL_DITHER);
    ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  }
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_PROJECTION);
  EXPECT_EQ(GetFloat(GL_COLOR_CLEAR_VALUE), 0.5f);
}

// ---- glGetString -----------------------------------------------------------------

TEST_F(StateQueryTest, GetStrings) {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  ASSERT_NE(version, nullptr);
  if (kTestingAgainstMesa) {
    // Mesa is a "4.5 (Compatibility Profile) Mesa ..." context.
    EXPECT_TRUE(version[0] >= '2' && version[0] <= '9' && version[1] == '.') << version;
  } else {
    // No GLSL: the last version without shaders (api/gl_version.h).
    EXPECT_EQ(std::string(version).substr(0, 3), "1.5") << version;
    // §6.1.11: "major.minor" or "major.minor.release", then a space and vendor text.
    EXPECT_TRUE(version[3] == '\0' || version[3] == ' ' || version[3] == '.') << version;
  }
  const char* vendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
  ASSERT_NE(vendor, nullptr);
  EXPECT_GT(std::strlen(vendor), 0u);
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  ASSERT_NE(renderer, nullptr);
  EXPECT_GT(std::strlen(renderer), 0u);
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(extensions, nullptr);  // may be empty, but is a string
  EXPECT_LT(std::strlen(extensions), 1u << 20);
  // The same pointer's text stays valid and unchanged.
  EXPECT_STREQ(reinterpret_cast<const char*>(glGetString(GL_VERSION)), version);
  EXPECT_NO_GL_ERROR();
}

// "Say only what is true": every extension the library advertises has all
// its commands behind GetProcAddress; shaders have none (there is no GLSL),
// and GL_SHADING_LANGUAGE_VERSION is not a name of a GL 1.5 context.
TEST_F(StateQueryTest, AdvertisedExtensionsHaveTheirCommands) {
  const std::map<std::string, std::vector<const char*>> commands = {
      {"GL_ARB_point_parameters", {"glPointParameterfARB", "glPointParameterfvARB"}},
      {"GL_EXT_point_parameters", {"glPointParameterfEXT", "glPointParameterfvEXT"}},
      {"GL_ARB_provoking_vertex", {"glProvokingVertex"}},
      {"GL_EXT_provoking_vertex", {"glProvokingVertexEXT"}},
      {"GL_ARB_transpose_matrix",
       {"glLoadTransposeMatrixfARB", "glLoadTransposeMatrixdARB", "glMultTransposeMatrixfARB",
        "glMultTransposeMatrixdARB"}},
      {"GL_ARB_vertex_buffer_object",
       {"glBindBufferARB", "glDeleteBuffersARB", "glGenBuffersARB", "glIsBufferARB", "glBufferDataARB",
        "glBufferSubDataARB", "glGetBufferSubDataARB", "glMapBufferARB", "glUnmapBufferARB",
        "glGetBufferParameterivARB", "glGetBufferPointervARB"}},
      {"GL_ARB_map_buffer_range", {"glMapBufferRange", "glFlushMappedBufferRange"}},
      {"GL_ARB_copy_buffer", {"glCopyBufferSubData"}},
      {"GL_NV_primitive_restart", {"glPrimitiveRestartNV", "glPrimitiveRestartIndexNV"}},
      {"GL_ARB_draw_elements_base_vertex",
       {"glDrawElementsBaseVertex", "glDrawRangeElementsBaseVertex", "glMultiDrawElementsBaseVertex"}},
      {"GL_ARB_vertex_array_object", {"glBindVertexArray", "glDeleteVertexArrays", "glGenVertexArrays", "glIsVertexArray"}},
      {"GL_EXT_draw_range_elements", {"glDrawRangeElementsEXT"}},
      {"GL_ARB_multisample", {"glSampleCoverageARB"}},
      {"GL_ARB_occlusion_query",
       {"glGenQueriesARB", "glDeleteQueriesARB", "glIsQueryARB", "glBeginQueryARB", "glEndQueryARB",
        "glGetQueryivARB", "glGetQueryObjectivARB", "glGetQueryObjectuivARB"}},
      {"GL_ARB_framebuffer_object", {"glIsRenderbuffer", "glBindRenderbuffer", "glDeleteRenderbuffers", "glGenRenderbuffers", "glRenderbufferStorage", "glGetRenderbufferParameteriv", "glIsFramebuffer", "glBindFramebuffer", "glDeleteFramebuffers", "glGenFramebuffers", "glCheckFramebufferStatus", "glFramebufferTexture1D", "glFramebufferTexture2D", "glFramebufferTexture3D", "glFramebufferRenderbuffer", "glGetFramebufferAttachmentParameteriv", "glRenderbufferStorageMultisample", "glFramebufferTextureLayer", "glBlitFramebuffer", "glGenerateMipmap"}},
      {"GL_EXT_framebuffer_object", {"glIsRenderbufferEXT", "glBindRenderbufferEXT", "glDeleteRenderbuffersEXT", "glGenRenderbuffersEXT", "glRenderbufferStorageEXT", "glGetRenderbufferParameterivEXT", "glIsFramebufferEXT", "glBindFramebufferEXT", "glDeleteFramebuffersEXT", "glGenFramebuffersEXT", "glCheckFramebufferStatusEXT", "glFramebufferTexture1DEXT", "glFramebufferTexture2DEXT", "glFramebufferTexture3DEXT", "glFramebufferRenderbufferEXT", "glGetFramebufferAttachmentParameterivEXT", "glGenerateMipmapEXT"}},
      {"GL_EXT_framebuffer_blit", {"glBlitFramebufferEXT"}},
      {"GL_EXT_multi_draw_arrays", {"glMultiDrawArraysEXT", "glMultiDrawElementsEXT"}},
      {"GL_EXT_rescale_normal", {}},
      {"GL_ARB_multitexture",
       {"glMultiTexCoord1sARB", "glMultiTexCoord1svARB",   "glMultiTexCoord1iARB", "glMultiTexCoord1ivARB",
        "glMultiTexCoord1fARB", "glMultiTexCoord1fvARB",   "glMultiTexCoord1dARB", "glMultiTexCoord1dvARB",
        "glMultiTexCoord2sARB", "glMultiTexCoord2svARB",   "glMultiTexCoord2iARB", "glMultiTexCoord2ivARB",
        "glMultiTexCoord2fARB", "glMultiTexCoord2fvARB",   "glMultiTexCoord2dARB", "glMultiTexCoord2dvARB",
        "glMultiTexCoord3sARB", "glMultiTexCoord3svARB",   "glMultiTexCoord3iARB", "glMultiTexCoord3ivARB",
        "glMultiTexCoord3fARB", "glMultiTexCoord3fvARB",   "glMultiTexCoord3dARB", "glMultiTexCoord3dvARB",
        "glMultiTexCoord4sARB", "glMultiTexCoord4svARB",   "glMultiTexCoord4iARB", "glMultiTexCoord4ivARB",
        "glMultiTexCoord4fARB", "glMultiTexCoord4fvARB",   "glMultiTexCoord4dARB", "glMultiTexCoord4dvARB",
        "glActiveTextureARB",   "glClientActiveTextureARB"}},
      {"GL_EXT_texture3D", {"glTexImage3DEXT", "glTexSubImage3DEXT"}},
      {"GL_EXT_subtexture", {"glTexSubImage1DEXT", "glTexSubImage2DEXT"}},
      {"GL_EXT_copy_texture",
       {"glCopyTexImage1DEXT", "glCopyTexImage2DEXT", "glCopyTexSubImage1DEXT", "glCopyTexSubImage2DEXT",
        "glCopyTexSubImage3DEXT"}},
      {"GL_EXT_texture_object",
       {"glAreTexturesResidentEXT", "glBindTextureEXT", "glDeleteTexturesEXT", "glGenTexturesEXT",
        "glIsTextureEXT", "glPrioritizeTexturesEXT"}},
      {"GL_ARB_texture_border_clamp", {}},
      {"GL_ARB_depth_texture", {}},
      {"GL_ARB_depth_clamp", {}},
      {"GL_ARB_shadow", {}},
      {"GL_ARB_point_sprite", {}},
      {"GL_ARB_texture_cube_map", {}},
      {"GL_ARB_texture_env_add", {}},
      {"GL_ARB_texture_env_combine", {}},
      {"GL_ARB_texture_env_crossbar", {}},
      {"GL_ARB_texture_env_dot3", {}},
      {"GL_ARB_texture_mirrored_repeat", {}},
      {"GL_ARB_texture_float", {}},
      {"GL_ARB_texture_non_power_of_two", {}},
      {"GL_EXT_bgra", {}},
      {"GL_EXT_packed_pixels", {}},
      {"GL_EXT_packed_depth_stencil", {}},
      {"GL_ARB_pixel_buffer_object", {}},
      {"GL_EXT_vertex_array_bgra", {}},
      {"GL_MESA_pack_invert", {}},
      {"GL_EXT_pixel_buffer_object", {}},
      {"GL_EXT_texture", {}},
      {"GL_EXT_texture_edge_clamp", {}},
      {"GL_EXT_texture_env_add", {}},
      {"GL_EXT_texture_env_combine", {}},
      {"GL_EXT_texture_env_dot3", {}},
      {"GL_EXT_texture_lod_bias", {}},
      {"GL_SGIS_generate_mipmap", {}},
      {"GL_SGIS_texture_border_clamp", {}},
      {"GL_SGIS_texture_edge_clamp", {}},
      {"GL_SGIS_texture_lod", {}},
      {"GL_EXT_separate_specular_color", {}},
      {"GL_EXT_blend_color", {"glBlendColorEXT"}},
      {"GL_EXT_blend_minmax", {"glBlendEquationEXT"}},
      {"GL_EXT_blend_subtract", {"glBlendEquationEXT"}},
      {"GL_EXT_blend_func_separate", {"glBlendFuncSeparateEXT"}},
      {"GL_INGR_blend_func_separate", {"glBlendFuncSeparateINGR"}},
      {"GL_EXT_blend_equation_separate", {"glBlendEquationSeparateEXT"}},
      {"GL_ATI_blend_equation_separate", {"glBlendEquationSeparateATI"}},
      {"GL_NV_blend_square", {}},
      {"GL_EXT_fog_coord",
       {"glFogCoordfEXT", "glFogCoordfvEXT", "glFogCoorddEXT", "glFogCoorddvEXT", "glFogCoordPointerEXT"}},
      {"GL_NV_fog_distance", {}},
      {"GL_EXT_vertex_array",
       {"glArrayElementEXT", "glDrawArraysEXT", "glGetPointervEXT", "glVertexPointerEXT",
        "glNormalPointerEXT", "glColorPointerEXT", "glIndexPointerEXT", "glTexCoordPointerEXT",
        "glEdgeFlagPointerEXT"}},
      {"GL_EXT_stencil_wrap", {}},
      {"GL_EXT_shadow_funcs", {}},
      {"GL_EXT_stencil_two_side", {"glActiveStencilFaceEXT"}},
      {"GL_ATI_separate_stencil", {"glStencilFuncSeparateATI", "glStencilOpSeparateATI"}},
      {"GL_ARB_window_pos",
       {"glWindowPos2sARB", "glWindowPos2svARB", "glWindowPos2iARB", "glWindowPos2ivARB", "glWindowPos2fARB", "glWindowPos2fvARB", "glWindowPos2dARB", "glWindowPos2dvARB", "glWindowPos3sARB", "glWindowPos3svARB", "glWindowPos3iARB", "glWindowPos3ivARB", "glWindowPos3fARB", "glWindowPos3fvARB", "glWindowPos3dARB", "glWindowPos3dvARB"}},
  };
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(extensions, nullptr);
  std::istringstream words(extensions);
  std::string name;
  int known = 0;
  while (words >> name) {
    auto it = commands.find(name);
    if (it == commands.end()) {
      if (!kTestingAgainstMesa) ADD_FAILURE() << name << " is advertised but not checked here";
      continue;
    }
    ++known;
    for (const char* command : it->second)
      EXPECT_NE(reinterpret_cast<void*>(OSMesaGetProcAddress(command)), nullptr) << name << ": " << command;
  }
  EXPECT_GT(known, 0);
  if (kTestingAgainstMesa) return;
  for (const char* glsl : {"glCreateShader", "glShaderSource", "glUseProgram", "glUniform1f"})
    EXPECT_EQ(reinterpret_cast<void*>(OSMesaGetProcAddress(glsl)), nullptr) << glsl;
  EXPECT_EQ(glGetString(GL_SHADING_LANGUAGE_VERSION), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// The colour-index state of an RGBA context: stored, pushed and listed.
TEST_F(StateQueryTest, ClearIndexAndIndexMask) {
  GLint mask = 0;
  glGetIntegerv(GL_INDEX_WRITEMASK, &mask);
  EXPECT_EQ(mask, -1);
  glIndexMask(0x1234);
  glClearIndex(7.5f);
  GLfloat index = 0;
  glGetFloatv(GL_INDEX_CLEAR_VALUE, &index);
  EXPECT_EQ(index, 7.0f);  // Mesa keeps an unsigned integer
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glIndexMask(5);
  glClearIndex(2);
  glPopAttrib();
  glGetIntegerv(GL_INDEX_WRITEMASK, &mask);
  EXPECT_EQ(mask, 0x1234);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glIndexMask(9);
  glEndList();
  glGetIntegerv(GL_INDEX_WRITEMASK, &mask);
  EXPECT_EQ(mask, 0x1234);
  glCallList(list);
  glGetIntegerv(GL_INDEX_WRITEMASK, &mask);
  EXPECT_EQ(mask, 9);
  glDeleteLists(list, 1);
  glBegin(GL_POINTS);
  glIndexMask(1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glClearIndex(1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

TEST_F(StateQueryTest, GetStringOfABadNameIsNullAndInvalidEnum) {
  EXPECT_EQ(glGetString(GL_DEPTH_TEST), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(glGetString(0xFFFF), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
