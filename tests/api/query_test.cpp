// Occlusion queries (GL 2.1 §4.1.7, ARB_occlusion_query): what
// GL_SAMPLES_PASSED counts (fragments past every test, not the colour mask,
// not glClear; glDrawPixels, glCopyPixels and glBitmap fragments too), the
// names, the errors and display lists. Built against Mesa too: every
// expectation was measured on Mesa 22.3 (llvmpipe).
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

GLint GetQueryiv(GLenum pname) {
  GLint value = -1;
  glGetQueryiv(GL_SAMPLES_PASSED, pname, &value);
  return value;
}

class QueryTest : public GLTest {
 protected:
  void SetUp() override {
    GLTest::SetUp();
    // One unit a pixel, so that integer rectangles cover exactly their area.
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, kWidth, 0, kHeight, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glGenQueries(1, &query_);
  }
  // The samples `draw` passes, counted by one query.
  template <typename Draw>
  GLuint count(Draw draw) {
    glBeginQuery(GL_SAMPLES_PASSED, query_);
    draw();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint result = 12345;
    glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &result);
    return result;
  }
  GLuint query_ = 0;
};

TEST_F(QueryTest, CountsCoveredFragments) {
  EXPECT_EQ(count([] { glRecti(2, 3, 12, 8); }), 50u);
  EXPECT_EQ(count([] {}), 0u);
  EXPECT_EQ(count([] { glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); }), 0u);
  GLint available = 0;
  glGetQueryObjectiv(query_, GL_QUERY_RESULT_AVAILABLE, &available);
  EXPECT_EQ(available, GL_TRUE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(QueryTest, CountsOnlyWhatPassesTheTests) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  // The second rectangle fails GL_LESS where the first wrote the same depth.
  EXPECT_EQ(count([] {
              glRecti(0, 0, 10, 10);
              glRecti(0, 0, 20, 10);
            }),
            200u);
  // Masked colour and depth writes are still counted.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_ALWAYS);
  EXPECT_EQ(count([] { glRecti(0, 0, 20, 10); }), 200u);
  glDepthFunc(GL_LESS);
  EXPECT_EQ(count([] { glRecti(0, 0, 20, 10); }), 0u);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  // The alpha test discards before the count.
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(1, 1, 1, 0.25f);
  EXPECT_EQ(count([] { glRecti(0, 0, 8, 8); }), 0u);
  glColor4f(1, 1, 1, 0.75f);
  EXPECT_EQ(count([] { glRecti(0, 0, 8, 8); }), 64u);
  glDisable(GL_ALPHA_TEST);
  // The scissor cuts what is counted.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 4, 4);
  EXPECT_EQ(count([] { glRecti(0, 0, 8, 8); }), 16u);
  glDisable(GL_SCISSOR_TEST);
  EXPECT_NO_GL_ERROR();
}

TEST_F(QueryTest, CountsTheStencilTest) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  ASSERT_NE(ctx, nullptr);
  std::vector<unsigned char> buffer(kWidth * kHeight * 4);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight));
  glOrtho(0, kWidth, 0, kHeight, -1, 1);
  GLuint q = 0;
  glGenQueries(1, &q);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glRecti(0, 0, 6, 6);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glRecti(0, 0, 12, 12);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint result = 0;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &result);
  EXPECT_EQ(result, 36u);
  EXPECT_NO_GL_ERROR();
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

TEST_F(QueryTest, CountsPixelRectangles) {
  std::vector<GLubyte> image(8 * 4 * 4, 200);
  glRasterPos2i(10, 10);
  EXPECT_EQ(count([&] { glDrawPixels(8, 4, GL_RGBA, GL_UNSIGNED_BYTE, image.data()); }), 32u);
  // Not overlapping and plain: Mesa would blit, but not under a query.
  glRasterPos2i(40, 40);
  EXPECT_EQ(count([] { glCopyPixels(10, 10, 8, 4, GL_COLOR); }), 32u);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const GLubyte bits[4] = {0xff, 0x0f, 0x00, 0x81};  // 8 + 4 + 0 + 2 set bits
  glRasterPos2i(20, 30);
  EXPECT_EQ(count([&] { glBitmap(8, 4, 0, 0, 0, 0, bits); }), 14u);
  // A bitmap drawn before the query is not counted in it, though Mesa caches it.
  glRasterPos2i(20, 50);
  glBitmap(8, 4, 0, 0, 0, 0, bits);
  EXPECT_EQ(count([] {}), 0u);
  EXPECT_NO_GL_ERROR();
}

TEST_F(QueryTest, BufferedVerticesCountWhereTheyWereDrawn) {
  // Vertices drawn before glBeginQuery are not counted, those before
  // glEndQuery are, though glBegin/glEnd may still hold them.
  glBegin(GL_QUADS);
  glVertex2i(0, 0);
  glVertex2i(4, 0);
  glVertex2i(4, 4);
  glVertex2i(0, 4);
  glEnd();
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glBegin(GL_QUADS);
  glVertex2i(10, 0);
  glVertex2i(12, 0);
  glVertex2i(12, 3);
  glVertex2i(10, 3);
  glEnd();
  glEndQuery(GL_SAMPLES_PASSED);
  glBegin(GL_QUADS);
  glVertex2i(20, 0);
  glVertex2i(30, 0);
  glVertex2i(30, 10);
  glVertex2i(20, 10);
  glEnd();
  GLuint result = 0;
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &result);
  EXPECT_EQ(result, 6u);
}

TEST_F(QueryTest, NamesAndQueries) {
  EXPECT_EQ(glIsQuery(query_), GL_FALSE);  // generated, never begun
  EXPECT_EQ(GetQueryiv(GL_QUERY_COUNTER_BITS), 64);
  EXPECT_EQ(GetQueryiv(GL_CURRENT_QUERY), 0);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  EXPECT_EQ(glIsQuery(query_), GL_TRUE);
  EXPECT_EQ(GetQueryiv(GL_CURRENT_QUERY), static_cast<GLint>(query_));
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(GetQueryiv(GL_CURRENT_QUERY), 0);
  // A name glGenQueries never gave may begin a query (GL 2.1, not core).
  glBeginQuery(GL_SAMPLES_PASSED, 777);
  EXPECT_NO_GL_ERROR();
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_EQ(glIsQuery(777), GL_TRUE);
  GLuint names[2] = {};
  glGenQueries(2, names);
  EXPECT_NE(names[0], names[1]);
  EXPECT_NE(names[0], query_);
  EXPECT_NE(names[0], 0u);
  // Deleting the active query ends it.
  glBeginQuery(GL_SAMPLES_PASSED, names[0]);
  glDeleteQueries(1, &names[0]);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetQueryiv(GL_CURRENT_QUERY), 0);
  EXPECT_EQ(glIsQuery(names[0]), GL_FALSE);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDeleteQueries(1, &query_);
  EXPECT_EQ(glIsQuery(query_), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(QueryTest, Errors) {
  GLuint other = 0;
  glGenQueries(1, &other);
  glGenQueries(-1, &other);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteQueries(-1, &other);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glBeginQuery(GL_SAMPLES_PASSED, 0);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBeginQuery(GL_TEXTURE_2D, query_);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  GLuint result = 99;
  glGetQueryObjectuiv(other, GL_QUERY_RESULT, &result);  // never begun
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetQueryObjectuiv(4321, GL_QUERY_RESULT, &result);  // no such query
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glBeginQuery(GL_SAMPLES_PASSED, other);  // one is active already
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &result);  // still active
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(result, 99u);
  glEndQuery(GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glEndQuery(GL_SAMPLES_PASSED);
  EXPECT_NO_GL_ERROR();
  glGetQueryObjectuiv(query_, GL_TEXTURE_2D, &result);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLint value = 0;
  glGetQueryiv(GL_TEXTURE_2D, GL_CURRENT_QUERY, &value);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_TEXTURE_2D, &value);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_TRIANGLES);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetQueryiv(GL_CURRENT_QUERY), 0);
}

TEST_F(QueryTest, DisplayListsHoldBeginAndEnd) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBeginQuery(GL_SAMPLES_PASSED, query_);
  glRecti(0, 0, 8, 4);
  glEndQuery(GL_SAMPLES_PASSED);
  glEndList();
  EXPECT_EQ(glIsQuery(query_), GL_FALSE);  // compiled, not run
  glCallList(list);
  GLuint result = 0;
  glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &result);
  EXPECT_EQ(result, 32u);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
