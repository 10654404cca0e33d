// Errors (GL 2.1 §2.5): GL_INVALID_ENUM, GL_INVALID_VALUE and
// GL_INVALID_OPERATION, each leaving the state it would have changed as it
// was; the commands allowed and refused between glBegin and glEnd (§2.6.3);
// the first error kept until glGetError reads it.
#include <functional>
#include <string>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using ErrorTest = GLTest;

// Values that are no enum of the command they are passed to.
constexpr GLenum kBogus = 0xFFFF;
constexpr GLenum kBogus2 = 0x1234;

// T(1,2,3) * S(2,3,4), column-major.
const double kScaleThenTranslate[16] = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 1, 2, 3, 1};

// ---- GL_INVALID_ENUM --------------------------------------------------------------

TEST_F(ErrorTest, EnableDisableIsEnabledOfABadCap) {
  for (GLenum cap :
       {kBogus, kBogus2, static_cast<GLenum>(GL_DEPTH_FUNC), static_cast<GLenum>(GL_TRIANGLES)}) {
    SCOPED_TRACE(::testing::Message() << "cap 0x" << std::hex << cap);
    glEnable(cap);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    glDisable(cap);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ErrorTest, MatrixModeBadEnum) {
  glMatrixMode(GL_PROJECTION);
  glMatrixMode(kBogus);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glMatrixMode(GL_DEPTH_TEST);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_PROJECTION);
}

TEST_F(ErrorTest, DepthFuncBadEnum) {
  glDepthFunc(GL_GEQUAL);
  for (GLenum f : {static_cast<GLenum>(GL_NEVER - 1), static_cast<GLenum>(GL_ALWAYS + 1), kBogus}) {
    glDepthFunc(f);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_GEQUAL);
}

TEST_F(ErrorTest, CullFaceBadEnum) {
  glCullFace(GL_FRONT);
  for (GLenum m : {static_cast<GLenum>(GL_FRONT_LEFT), static_cast<GLenum>(GL_CW), kBogus}) {
    glCullFace(m);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(GetInt(GL_CULL_FACE_MODE), GL_FRONT);
}

TEST_F(ErrorTest, FrontFaceBadEnum) {
  glFrontFace(GL_CW);
  for (GLenum m : {static_cast<GLenum>(GL_FRONT), static_cast<GLenum>(GL_CCW + 1), kBogus}) {
    glFrontFace(m);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(GetInt(GL_FRONT_FACE), GL_CW);
}

TEST_F(ErrorTest, ShadeModelBadEnum) {
  glShadeModel(GL_FLAT);
  for (GLenum m : {static_cast<GLenum>(GL_SMOOTH + 1), static_cast<GLenum>(GL_FLAT - 1), kBogus}) {
    glShadeModel(m);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(GetInt(GL_SHADE_MODEL), GL_FLAT);
}

TEST_F(ErrorTest, ProvokingVertexBadEnum) {
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  glProvokingVertex(kBogus);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glProvokingVertex(GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_PROVOKING_VERTEX), GL_FIRST_VERTEX_CONVENTION);
}

// A refused glBegin does not start a primitive: the commands after it are
// outside glBegin/glEnd.
void ExpectBadBeginMode(GLenum mode) {
  SCOPED_TRACE(::testing::Message() << "mode 0x" << std::hex << mode);
  glBegin(mode);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glMatrixMode(GL_PROJECTION);  // allowed: not inside Begin/End
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_PROJECTION);
  glMatrixMode(GL_MODELVIEW);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

TEST_F(ErrorTest, BeginBadMode) {
  ExpectBadBeginMode(kBogus);
  ExpectBadBeginMode(kBogus2);
  ExpectBadBeginMode(GL_DEPTH_TEST);
}

// GL 2.1 has the modes GL_POINTS (0) to GL_POLYGON (9). GL 3.2 added the
// adjacency modes 0xA to 0xD, which a GL 4.5 context (Mesa) accepts.
TEST_F(ErrorTest, BeginAdjacencyModesAreNotGL21) {
  GLFX_SKIP_ON_MESA("GL_LINES_ADJACENCY (0xA) .. GL_TRIANGLE_STRIP_ADJACENCY (0xD) are valid since GL 3.2");
  for (GLenum mode = 0xA; mode <= 0xD; ++mode) ExpectBadBeginMode(mode);
}

TEST_F(ErrorTest, GetOfABadPname) {
  const GLenum bad[] = {kBogus, kBogus2, GL_TRIANGLES + 0x100 /* 0x104 */};
  for (GLenum pname : bad) {
    SCOPED_TRACE(::testing::Message() << "pname 0x" << std::hex << pname);
    GLboolean b[4] = {7, 7, 7, 7};
    GLint i[4] = {-5, -5, -5, -5};
    GLfloat f[4] = {-5, -5, -5, -5};
    GLdouble d[4] = {-5, -5, -5, -5};
    glGetBooleanv(pname, b);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    glGetIntegerv(pname, i);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    glGetFloatv(pname, f);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    glGetDoublev(pname, d);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(b[k], 7) << "glGetBooleanv wrote to its output";
      EXPECT_EQ(i[k], -5) << "glGetIntegerv wrote to its output";
      EXPECT_EQ(f[k], -5.0f) << "glGetFloatv wrote to its output";
      EXPECT_EQ(d[k], -5.0) << "glGetDoublev wrote to its output";
    }
  }
}

TEST_F(ErrorTest, ReadPixelsBadFormatOrType) {
  unsigned char out[64];
  std::memset(out, 0x3C, sizeof out);
  for (GLenum type : {kBogus, kBogus2, static_cast<GLenum>(GL_RGBA)}) {
    glReadPixels(0, 0, 2, 2, GL_RGBA, type, out);
    EXPECT_GL_ERROR(GL_INVALID_ENUM) << "type 0x" << std::hex << type;
  }
  // §2.5, §3.6.4: a format not in table 3.6 is GL_INVALID_ENUM. Mesa 22 says
  // GL_INVALID_OPERATION for a bad format with a valid type.
  for (GLenum format : {kBogus, kBogus2, static_cast<GLenum>(GL_DEPTH_TEST)}) {
    glReadPixels(0, 0, 2, 2, format, GL_UNSIGNED_BYTE, out);
    EXPECT_GL_ERROR(kTestingAgainstMesa ? GL_INVALID_OPERATION : GL_INVALID_ENUM)
        << "format 0x" << std::hex << format;
  }
  for (unsigned char c : out) ASSERT_EQ(c, 0x3C) << "a refused glReadPixels wrote to memory";
}

// §4.3.2 (and §3.6.4): a packed type whose component count does not match the
// format is GL_INVALID_OPERATION.
TEST_F(ErrorTest, ReadPixelsPackedTypeOfTheWrongFormat) {
  unsigned char out[64];
  std::memset(out, 0x3C, sizeof out);
  glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  for (unsigned char c : out) ASSERT_EQ(c, 0x3C) << "a refused glReadPixels wrote to memory";
}

// ---- GL_INVALID_VALUE -------------------------------------------------------------

TEST_F(ErrorTest, ViewportNegativeSize) {
  glViewport(1, 2, 3, 4);
  glViewport(0, 0, -1, 10);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glViewport(0, 0, 10, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glViewport(5, 5, -100, -100);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  std::array<GLint, 4> v = GetInts<4>(GL_VIEWPORT);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[1], 2);
  EXPECT_EQ(v[2], 3);
  EXPECT_EQ(v[3], 4);
}

TEST_F(ErrorTest, FrustumBadValues) {
  const double bad[][6] = {
      {-1, 1, -1, 1, 0, 10},     // near == 0
      {-1, 1, -1, 1, -1, 10},    // near < 0
      {-1, 1, -1, 1, 1, 0},      // far == 0
      {-1, 1, -1, 1, 1, -10},    // far < 0
      {-1, 1, -1, 1, 2, 2},      // near == far
      {1, 1, -1, 1, 1, 10},      // left == right
      {-1, 1, 0.5, 0.5, 1, 10},  // bottom == top
  };
  for (GLenum mode : {GL_MODELVIEW, GL_PROJECTION}) {
    glMatrixMode(mode);
    glLoadMatrixd(kScaleThenTranslate);
    for (const auto& c : bad) {
      SCOPED_TRACE(::testing::Message() << "glFrustum(" << c[0] << ", " << c[1] << ", " << c[2] << ", "
                                        << c[3] << ", " << c[4] << ", " << c[5] << ")");
      glFrustum(c[0], c[1], c[2], c[3], c[4], c[5]);
      EXPECT_GL_ERROR(GL_INVALID_VALUE);
    }
    EXPECT_TRUE(MatrixIs(mode == GL_MODELVIEW ? GL_MODELVIEW_MATRIX : GL_PROJECTION_MATRIX,
                         TranslationRef(1, 2, 3) * ScaleRef(2, 3, 4)));
  }
}

TEST_F(ErrorTest, OrthoBadValues) {
  const double bad[][6] = {
      {1, 1, -1, 1, -1, 1},  // left == right
      {-1, 1, 2, 2, -1, 1},  // bottom == top
      {-1, 1, -1, 1, 3, 3},  // near == far
      {0, 0, 0, 0, 0, 0},
  };
  glMatrixMode(GL_PROJECTION);
  glTranslatef(1, 2, 3);
  for (const auto& c : bad) {
    SCOPED_TRACE(::testing::Message() << "glOrtho(" << c[0] << ", " << c[1] << ", " << c[2] << ", " << c[3]
                                      << ", " << c[4] << ", " << c[5] << ")");
    glOrtho(c[0], c[1], c[2], c[3], c[4], c[5]);
    EXPECT_GL_ERROR(GL_INVALID_VALUE);
  }
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, TranslationRef(1, 2, 3)));
}

TEST_F(ErrorTest, ReadPixelsNegativeSize) {
  unsigned char out[64];
  std::memset(out, 0x3C, sizeof out);
  glReadPixels(0, 0, -1, 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glReadPixels(0, 0, 2, -1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  for (unsigned char c : out) ASSERT_EQ(c, 0x3C) << "a refused glReadPixels wrote to memory";
  glReadPixels(0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);  // empty is fine
  EXPECT_NO_GL_ERROR();
}

TEST_F(ErrorTest, ClearBadBits) {
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glClearColor(0, 1, 0, 1);
  const GLbitfield bad[] = {0x1, 0x80000000u, GL_COLOR_BUFFER_BIT | 0x2,
                            GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | 0x10000};
  for (GLbitfield mask : bad) {
    glClear(mask);
    EXPECT_GL_ERROR(GL_INVALID_VALUE) << "mask 0x" << std::hex << mask;
  }
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const unsigned char* p = pixels() + 4 * i;
    ASSERT_TRUE(p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255) << "pixel " << i << " was cleared";
  }
  glClear(0);  // nothing, and no error
  EXPECT_NO_GL_ERROR();
}

// ---- the error flag ---------------------------------------------------------------

TEST_F(ErrorTest, TheFirstErrorIsKeptUntilRead) {
  glEnable(kBogus);          // GL_INVALID_ENUM
  glViewport(0, 0, -1, -1);  // GL_INVALID_VALUE
  glEnd();                   // GL_INVALID_OPERATION
  glPopMatrix();             // GL_STACK_UNDERFLOW
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_NO_GL_ERROR() << "glGetError clears the flag";
  glPopMatrix();
  glEnable(kBogus);
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ErrorTest, AnErrorDoesNotStopLaterCommands) {
  glDepthFunc(kBogus);
  glDepthFunc(GL_EQUAL);  // runs although the flag is set
  EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_EQUAL);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ErrorTest, EndWithoutBegin) {
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glEnd();
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_NO_GL_ERROR();
}

// ---- between glBegin and glEnd (§2.6.3) ---------------------------------------------

// A command refused between glBegin and glEnd: `call` runs inside, `check`
// (after glEnd) asserts that nothing changed.
struct RefusedInside {
  const char* name;
  std::function<void()> setup;  // outside, before glBegin
  std::function<void()> call;
  std::function<void()> check;
};

class BeginEndTest : public GLTest {
 protected:
  void RunRefused(const RefusedInside& r) {
    SCOPED_TRACE(r.name);
    ASSERT_EQ(DrainErrors(), static_cast<GLenum>(GL_NO_ERROR));
    if (r.setup) r.setup();
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "setup";
    glBegin(GL_TRIANGLES);
    r.call();
    glEnd();
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    EXPECT_NO_GL_ERROR();
    if (r.check) r.check();
    EXPECT_NO_GL_ERROR() << "check";
  }
};

// §2.6.3: the only commands allowed between glBegin and glEnd are Vertex,
// Color, SecondaryColor, Index, Normal, TexCoord, MultiTexCoord, VertexAttrib,
// FogCoord, ArrayElement, EvalCoord, EvalPoint, Material, CallList(s) and
// EdgeFlag. Each is tried on its own, inside a primitive.
TEST_F(BeginEndTest, AllowedCommandsRaiseNoError) {
  static const GLfloat red[4] = {1, 0, 0, 1};
  static const GLubyte noList = 0;
  const struct {
    const char* name;
    std::function<void()> call;
  } allowed[] = {
      {"glVertex2f", [] { glVertex2f(0, 0); }},
      {"glVertex3f", [] { glVertex3f(1, 0, 0); }},
      {"glVertex4f", [] { glVertex4f(0, 1, 0, 1); }},
      {"glColor3f", [] { glColor3f(1, 0, 0); }},
      {"glColor4ub", [] { glColor4ub(1, 2, 3, 4); }},
      {"glNormal3f", [] { glNormal3f(0, 1, 0); }},
      {"glMaterialfv", [] { glMaterialfv(GL_FRONT, GL_DIFFUSE, red); }},
      {"glMaterialf", [] { glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 10.0f); }},
      {"glTexCoord2f", [] { glTexCoord2f(0.5f, 0.5f); }},
      {"glMultiTexCoord2f", [] { glMultiTexCoord2f(GL_TEXTURE0, 0.5f, 0.5f); }},
      {"glEdgeFlag", [] { glEdgeFlag(GL_TRUE); }},
      {"glSecondaryColor3f", [] { glSecondaryColor3f(0.1f, 0.2f, 0.3f); }},
      {"glFogCoordf", [] { glFogCoordf(1.0f); }},
      {"glIndexi", [] { glIndexi(0); }},
      {"glVertexAttrib4f", [] { glVertexAttrib4f(1, 0, 0, 0, 1); }},
      {"glArrayElement", [] { glArrayElement(0); }},
      {"glEvalCoord1f", [] { glEvalCoord1f(0.0f); }},
      {"glEvalPoint1", [] { glEvalPoint1(0); }},
      {"glCallList", [] { glCallList(12345); }},
      {"glCallLists", [] { glCallLists(1, GL_UNSIGNED_BYTE, &noList); }},
  };
  for (const auto& a : allowed) {
    // Vertex arrays, evaluators and display lists come in later issues: a
    // command the library does not implement yet has no address and is
    // checked once it has one.
    if (!OSMesaGetProcAddress(a.name)) continue;
    glBegin(GL_POINTS);
    a.call();
    glEnd();
    EXPECT_EQ(DrainErrors(), static_cast<GLenum>(GL_NO_ERROR)) << a.name << " between glBegin and glEnd";
  }
}

TEST_F(BeginEndTest, AttributesSetInsideAreCurrentAfterEnd) {
  glBegin(GL_LINES);
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glNormal3f(1, 0, 0);
  glVertex2f(0, 0);
  glColor4f(0.5f, 0.25f, 0.125f, 0.5f);
  glNormal3f(0, -1, 0);
  glVertex2f(1, 1);
  glEnd();
  std::array<GLfloat, 4> c = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_EQ(c[0], 0.5f);
  EXPECT_EQ(c[1], 0.25f);
  EXPECT_EQ(c[2], 0.125f);
  EXPECT_EQ(c[3], 0.5f);
  std::array<GLfloat, 3> n = GetFloats<3>(GL_CURRENT_NORMAL);
  EXPECT_EQ(n[0], 0.0f);
  EXPECT_EQ(n[1], -1.0f);
  EXPECT_EQ(n[2], 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(BeginEndTest, NestedBegin) {
  RunRefused({"glBegin", nullptr, [] { glBegin(GL_POINTS); },
              [] {
                // The outer glBegin was closed by the one glEnd.
                glEnd();
                EXPECT_GL_ERROR(GL_INVALID_OPERATION);
              }});
}

TEST_F(BeginEndTest, MatrixCommands) {
  const double m[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 1, 1, 1};
  auto setup = [m] {
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(m);
  };
  auto unchanged = [m] {
    EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_MODELVIEW);
    EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 1);
    EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(m)));
    EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, Identity()));
  };
  const float mf[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 5, 5, 1};
  const RefusedInside cases[] = {
      {"glMatrixMode", setup, [] { glMatrixMode(GL_PROJECTION); }, unchanged},
      {"glLoadIdentity", setup, [] { glLoadIdentity(); }, unchanged},
      {"glLoadMatrixf", setup, [mf] { glLoadMatrixf(mf); }, unchanged},
      {"glLoadMatrixd", setup, [] { glLoadMatrixd(kScaleThenTranslate); }, unchanged},
      {"glMultMatrixf", setup, [mf] { glMultMatrixf(mf); }, unchanged},
      {"glMultMatrixd", setup, [] { glMultMatrixd(kScaleThenTranslate); }, unchanged},
      {"glTranslatef", setup, [] { glTranslatef(1, 2, 3); }, unchanged},
      {"glTranslated", setup, [] { glTranslated(1, 2, 3); }, unchanged},
      {"glRotatef", setup, [] { glRotatef(30, 0, 0, 1); }, unchanged},
      {"glRotated", setup, [] { glRotated(30, 0, 0, 1); }, unchanged},
      {"glScalef", setup, [] { glScalef(2, 2, 2); }, unchanged},
      {"glScaled", setup, [] { glScaled(2, 2, 2); }, unchanged},
      {"glFrustum", setup, [] { glFrustum(-1, 1, -1, 1, 1, 10); }, unchanged},
      {"glOrtho", setup, [] { glOrtho(-1, 1, -1, 1, -1, 1); }, unchanged},
      {"glPushMatrix", setup, [] { glPushMatrix(); }, unchanged},
  };
  for (const RefusedInside& r : cases) RunRefused(r);
  RunRefused({"glPopMatrix",
              [m] {
                glLoadIdentity();
                glPushMatrix();
                glLoadMatrixd(m);
              },
              [] { glPopMatrix(); },
              [m] {
                EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 2);
                EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(m)));
              }});
}

TEST_F(BeginEndTest, ViewportAndDepthRange) {
  RunRefused({"glViewport", [] { glViewport(1, 2, 3, 4); }, [] { glViewport(0, 0, 10, 10); },
              [] {
                std::array<GLint, 4> v = GetInts<4>(GL_VIEWPORT);
                EXPECT_EQ(v[0], 1);
                EXPECT_EQ(v[1], 2);
                EXPECT_EQ(v[2], 3);
                EXPECT_EQ(v[3], 4);
              }});
  RunRefused({"glDepthRange", nullptr, [] { glDepthRange(0.25, 0.5); },
              [] {
                std::array<GLdouble, 2> r = GetDoubles<2>(GL_DEPTH_RANGE);
                EXPECT_EQ(r[0], 0.0);
                EXPECT_EQ(r[1], 1.0);
              }});
}

TEST_F(BeginEndTest, ClearAndClearValues) {
  auto setup = [] {
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  };
  auto red = [this] {
    for (int i = 0; i < kWidth * kHeight; ++i) {
      const unsigned char* p = pixels() + 4 * i;
      ASSERT_TRUE(p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255) << "pixel " << i << " changed";
    }
    std::array<GLfloat, 4> c = GetFloats<4>(GL_COLOR_CLEAR_VALUE);
    EXPECT_EQ(c[0], 1.0f);
    EXPECT_EQ(c[1], 0.0f);
  };
  RunRefused({"glClear", setup,
              [] {
                glClearColor(0, 0, 1, 1);  // refused too
                glClear(GL_COLOR_BUFFER_BIT);
              },
              red});
  RunRefused({"glClearColor", setup, [] { glClearColor(0, 1, 0, 1); }, red});
  RunRefused({"glClearDepth", [] { glClearDepth(0.5); }, [] { glClearDepth(0.25); },
              [] { EXPECT_EQ(GetDouble(GL_DEPTH_CLEAR_VALUE), 0.5); }});
}

TEST_F(BeginEndTest, EnableDisableIsEnabled) {
  RunRefused({"glEnable", nullptr, [] { glEnable(GL_DEPTH_TEST); },
              [] { EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE); }});
  RunRefused({"glDisable", nullptr, [] { glDisable(GL_DITHER); },
              [] { EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE); }});
  RunRefused({"glEnable(GL_LIGHTING)", nullptr, [] { glEnable(GL_LIGHTING); },
              [] { EXPECT_EQ(glIsEnabled(GL_LIGHTING), GL_FALSE); }});
  RunRefused({"glIsEnabled", nullptr,
              [] { EXPECT_EQ(glIsEnabled(GL_DITHER), GL_FALSE) << "returns 0 inside"; }, nullptr});
}

TEST_F(BeginEndTest, Queries) {
  RunRefused({"glGetIntegerv", nullptr,
              [] {
                GLint v[4] = {-7, -7, -7, -7};
                glGetIntegerv(GL_VIEWPORT, v);
                for (GLint x : v) EXPECT_EQ(x, -7) << "wrote its output";
              },
              nullptr});
  RunRefused({"glGetFloatv", nullptr,
              [] {
                GLfloat v[4] = {-7, -7, -7, -7};
                glGetFloatv(GL_CURRENT_COLOR, v);
                for (GLfloat x : v) EXPECT_EQ(x, -7.0f) << "wrote its output";
              },
              nullptr});
  RunRefused({"glGetDoublev", nullptr,
              [] {
                GLdouble v[16];
                for (GLdouble& x : v) x = -7;
                glGetDoublev(GL_MODELVIEW_MATRIX, v);
                for (GLdouble x : v) EXPECT_EQ(x, -7.0) << "wrote its output";
              },
              nullptr});
  RunRefused({"glGetBooleanv", nullptr,
              [] {
                GLboolean v[4] = {9, 9, 9, 9};
                glGetBooleanv(GL_DITHER, v);
                EXPECT_EQ(v[0], 9) << "wrote its output";
              },
              nullptr});
  RunRefused({"glGetString", nullptr, [] { EXPECT_EQ(glGetString(GL_VERSION), nullptr); }, nullptr});
}

// glGetError is not among the commands allowed between glBegin and glEnd: it
// raises GL_INVALID_OPERATION and, as a refused command, returns 0 without
// reading the flag.
TEST_F(BeginEndTest, GetErrorInsideReturnsZero) {
  RunRefused(
      {"glGetError", nullptr, [] { EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)); }, nullptr});
}

TEST_F(BeginEndTest, GetErrorInsideLeavesAnEarlierError) {
  glEnable(kBogus);  // GL_INVALID_ENUM, pending
  glBegin(GL_POINTS);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glVertex2f(0, 0);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_ENUM) << "the first error is kept, not read or replaced inside Begin/End";
  EXPECT_NO_GL_ERROR();
}

TEST_F(BeginEndTest, FlushFinish) {
  RunRefused({"glFlush", nullptr, [] { glFlush(); }, nullptr});
  RunRefused({"glFinish", nullptr, [] { glFinish(); }, nullptr});
}

TEST_F(BeginEndTest, DepthAndPolygonState) {
  RunRefused({"glDepthFunc", nullptr, [] { glDepthFunc(GL_ALWAYS); },
              [] { EXPECT_EQ(GetInt(GL_DEPTH_FUNC), GL_LESS); }});
  RunRefused({"glDepthMask", nullptr, [] { glDepthMask(GL_FALSE); },
              [] { EXPECT_EQ(GetBool(GL_DEPTH_WRITEMASK), GL_TRUE); }});
  RunRefused({"glCullFace", nullptr, [] { glCullFace(GL_FRONT); },
              [] { EXPECT_EQ(GetInt(GL_CULL_FACE_MODE), GL_BACK); }});
  RunRefused(
      {"glFrontFace", nullptr, [] { glFrontFace(GL_CW); }, [] { EXPECT_EQ(GetInt(GL_FRONT_FACE), GL_CCW); }});
  RunRefused({"glShadeModel", nullptr, [] { glShadeModel(GL_FLAT); },
              [] { EXPECT_EQ(GetInt(GL_SHADE_MODEL), GL_SMOOTH); }});
  RunRefused({"glProvokingVertex", nullptr, [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); },
              [] { EXPECT_EQ(GetInt(GL_PROVOKING_VERTEX), GL_LAST_VERTEX_CONVENTION); }});
}

TEST_F(BeginEndTest, LightingState) {
  RunRefused({"glLightf", nullptr, [] { glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 5.0f); },
              [] {
                GLfloat e = -1;
                glGetLightfv(GL_LIGHT0, GL_SPOT_EXPONENT, &e);
                EXPECT_EQ(e, 0.0f);
              }});
  RunRefused({"glLightModeli", nullptr, [] { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE); },
              [] { EXPECT_EQ(GetBool(GL_LIGHT_MODEL_TWO_SIDE), GL_FALSE); }});
  RunRefused({"glColorMaterial", nullptr, [] { glColorMaterial(GL_FRONT, GL_EMISSION); },
              [] { EXPECT_EQ(GetInt(GL_COLOR_MATERIAL_PARAMETER), GL_AMBIENT_AND_DIFFUSE); }});
}

TEST_F(BeginEndTest, PixelCommands) {
  RunRefused({"glReadPixels", nullptr,
              [] {
                unsigned char out[16];
                std::memset(out, 0x3C, sizeof out);
                glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
                for (unsigned char c : out) EXPECT_EQ(c, 0x3C) << "wrote its output";
              },
              nullptr});
  RunRefused({"glPixelStorei", nullptr, [] { glPixelStorei(GL_PACK_ALIGNMENT, 1); },
              [] { EXPECT_EQ(GetInt(GL_PACK_ALIGNMENT), 4); }});
}

// A refused command inside Begin/End leaves the primitive open: glEnd still
// closes it without an error of its own, and the next glBegin works.
TEST_F(BeginEndTest, ARefusedCommandDoesNotEndThePrimitive) {
  glBegin(GL_TRIANGLES);
  glMatrixMode(GL_PROJECTION);
  glVertex2f(0, 0);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION) << "the primitive was closed by the first glEnd";
  glBegin(GL_POINTS);
  glEnd();
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
