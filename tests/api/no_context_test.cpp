// GL commands with no current context (before any context exists, and after
// OSMesaMakeCurrent(NULL, ...)): they do nothing, do not crash, write no
// output, and glGetError returns 0.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

// Every call a program might make without a context. Returns what glGetError
// gave at the end; the out-parameters record what the queries wrote.
struct NoContextResults {
  bool ran = false;
  OSMesaContext current = reinterpret_cast<OSMesaContext>(1);
  GLenum firstError = 0xFFFF;
  GLenum lastError = 0xFFFF;
  const GLubyte* version = reinterpret_cast<const GLubyte*>(1);
  GLboolean enabled = 7;
  GLint ints[4] = {-3, -3, -3, -3};
  GLfloat floats[4] = {-3, -3, -3, -3};
  GLdouble doubles[16];
  GLboolean bools[4] = {7, 7, 7, 7};
  unsigned char pixels[64];
};

NoContextResults CallEverythingWithoutAContext() {
  NoContextResults r;
  for (GLdouble& d : r.doubles) d = -3;
  std::memset(r.pixels, 0x3C, sizeof r.pixels);
  r.current = OSMesaGetCurrentContext();
  r.firstError = glGetError();
  glEnable(0xFFFF);  // would be errors with a context
  glViewport(0, 0, -1, -1);
  glEnd();
  glPopMatrix();
  glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_DITHER);
  glDepthFunc(GL_ALWAYS);
  glDepthMask(GL_FALSE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glTranslatef(1, 2, 3);
  glRotatef(10, 1, 0, 0);
  glScaled(2, 2, 2);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glOrtho(-1, 1, -1, 1, -1, 1);
  for (int i = 0; i < 40; ++i) glPushMatrix();
  for (int i = 0; i < 40; ++i) glPopMatrix();
  glViewport(1, 2, 3, 4);
  glShadeModel(GL_FLAT);
  glCullFace(GL_FRONT);
  glFrontFace(GL_CW);
  glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  glColor4f(0.5f, 0.5f, 0.5f, 0.5f);
  glNormal3f(1, 0, 0);
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glVertex3f(0, 1, 0);
  glEnd();
  glFlush();
  glFinish();
  r.version = glGetString(GL_VERSION);
  r.enabled = glIsEnabled(GL_DITHER);
  glGetIntegerv(GL_VIEWPORT, r.ints);
  glGetFloatv(GL_CURRENT_COLOR, r.floats);
  glGetDoublev(GL_MODELVIEW_MATRIX, r.doubles);
  glGetBooleanv(GL_DEPTH_WRITEMASK, r.bools);
  glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, r.pixels);
  r.lastError = glGetError();
  r.ran = true;
  return r;
}

void ExpectNothingHappened(const NoContextResults& r) {
  ASSERT_TRUE(r.ran);
  EXPECT_EQ(r.current, nullptr) << "OSMesaGetCurrentContext";
  EXPECT_EQ(r.firstError, static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(r.lastError, static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(r.version, nullptr) << "glGetString";
  EXPECT_EQ(r.enabled, GL_FALSE) << "glIsEnabled";
  for (GLint v : r.ints) EXPECT_EQ(v, -3) << "glGetIntegerv wrote its output";
  for (GLfloat v : r.floats) EXPECT_EQ(v, -3.0f) << "glGetFloatv wrote its output";
  for (GLdouble v : r.doubles) EXPECT_EQ(v, -3.0) << "glGetDoublev wrote its output";
  for (GLboolean v : r.bools) EXPECT_EQ(v, 7) << "glGetBooleanv wrote its output";
  for (unsigned char c : r.pixels) ASSERT_EQ(c, 0x3C) << "glReadPixels wrote its output";
}

// Runs during static initialisation, before main() and before any test has
// created a context.
const NoContextResults g_beforeAnyContext = CallEverythingWithoutAContext();

TEST(NoContextTest, BeforeAnyContextCommandsDoNothing) { ExpectNothingHappened(g_beforeAnyContext); }

TEST(NoContextTest, AfterReleaseCommandsDoNothing) {
  ScopedContext c(OSMESA_RGBA, 24, kWidth, kHeight, 4);
  ASSERT_TRUE(c.makeCurrent());
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(5, 6, 7, 8);
  glEnable(GL_CULL_FACE);
  glEnable(0xFFFF);  // a pending GL_INVALID_ENUM in the context
  glFinish();        // the client buffer is up to date
  ASSERT_EQ(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0), GL_TRUE) << "releasing the current context";
  std::vector<unsigned char> before(c.bytes(), c.bytes() + kWidth * kHeight * 4);

  ExpectNothingHappened(CallEverythingWithoutAContext());
  EXPECT_EQ(std::memcmp(before.data(), c.bytes(), before.size()), 0) << "the released buffer was drawn to";

  // The context itself was not touched either.
  ASSERT_TRUE(c.makeCurrent());
  EXPECT_EQ(OSMesaGetCurrentContext(), c.get());
  EXPECT_GL_ERROR(GL_INVALID_ENUM) << "its pending error survives";
  EXPECT_NO_GL_ERROR();
  std::array<GLint, 4> v = GetInts<4>(GL_VIEWPORT);
  EXPECT_EQ(v[0], 5);
  EXPECT_EQ(v[1], 6);
  EXPECT_EQ(v[2], 7);
  EXPECT_EQ(v[3], 8);
  EXPECT_EQ(glIsEnabled(GL_CULL_FACE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_DITHER), GL_TRUE);
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_MODELVIEW);
  EXPECT_EQ(GetInt(GL_SHADE_MODEL), GL_SMOOTH);
  EXPECT_EQ(GetFloat(GL_COLOR_CLEAR_VALUE), 1.0f);
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, Identity()));
  EXPECT_EQ(GetFloat(GL_CURRENT_COLOR), 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST(NoContextTest, AfterDestroyingTheCurrentContext) {
  {
    ScopedContext c(OSMESA_RGBA, 24, 16, 16, 4);
    ASSERT_TRUE(c.makeCurrent());
    ASSERT_EQ(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0), GL_TRUE);
  }
  ExpectNothingHappened(CallEverythingWithoutAContext());
}

}  // namespace
}  // namespace glfx_test
