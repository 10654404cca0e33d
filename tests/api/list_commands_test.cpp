// Commands of the attribute stack, selection and feedback, the raster
// position, evaluators and vertex-array draws in display lists (GL 2.1 §5.4):
// compiled, not run, in GL_COMPILE; run once in GL_COMPILE_AND_EXECUTE; their
// client data (control points, array contents) captured at compile time; and
// the client-state commands executed at once. Run on Mesa too (mesa_api.*).
#include <vector>

#include "api/gl_test_fixture.h"

namespace glfx_test {
namespace {

class ListCommandsTest : public GLTest {
 protected:
  // Feedback of `draw` in GL_3D: the values written.
  static std::vector<GLfloat> Feedback(void (*draw)()) {
    static GLfloat buffer[1024];
    glFeedbackBuffer(1024, GL_3D, buffer);
    glRenderMode(GL_FEEDBACK);
    draw();
    const GLint n = glRenderMode(GL_RENDER);
    return std::vector<GLfloat>(buffer, buffer + (n > 0 ? n : 0));
  }
  // The number of GL_POINT_TOKENs in a feedback buffer of GL_3D points.
  static int Points(const std::vector<GLfloat>& f) {
    int points = 0;
    for (size_t i = 0; i < f.size(); i += 4)
      if (f[i] == GL_POINT_TOKEN) ++points;
    return points;
  }
};

TEST_F(ListCommandsTest, PushAndPopAttribAreCompiled) {
  glNewList(1, GL_COMPILE);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable(GL_DEPTH_TEST);
  glEndList();
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);  // not run
  glNewList(2, GL_COMPILE);
  glPopAttrib();
  glEndList();
  EXPECT_NO_GL_ERROR();  // an underflow would be raised when the list runs
  glCallList(1);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 1);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_TRUE);
  glCallList(2);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 0);
  EXPECT_EQ(glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
  glCallList(2);
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);  // the compiled pop's error, at replay
  glNewList(3, GL_COMPILE_AND_EXECUTE);
  glPushAttrib(GL_CURRENT_BIT);
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 1);  // run once, now
  glEndList();
  EXPECT_EQ(GetInt(GL_ATTRIB_STACK_DEPTH), 1);
  glPopAttrib();
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, NameStackCommandsAreCompiled) {
  GLuint select[64];
  glSelectBuffer(64, select);
  glRenderMode(GL_SELECT);
  glInitNames();
  glNewList(1, GL_COMPILE);
  glPushName(3);
  glPushName(4);
  glLoadName(5);
  glPopName();
  glPushName(6);
  glEndList();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  glCallList(1);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 2);
  glNewList(2, GL_COMPILE_AND_EXECUTE);
  glPopName();
  glEndList();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 1);
  glNewList(3, GL_COMPILE);
  glInitNames();
  glEndList();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 1);
  glCallList(3);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  glRenderMode(GL_RENDER);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, PassThroughIsCompiled) {
  glNewList(1, GL_COMPILE);
  glPassThrough(7.0f);
  glEndList();
  const std::vector<GLfloat> f = Feedback([] { glCallList(1); });
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0], static_cast<GLfloat>(GL_PASS_THROUGH_TOKEN));
  EXPECT_EQ(f[1], 7.0f);
  // GL_COMPILE_AND_EXECUTE in feedback mode: one token, not two.
  EXPECT_EQ(Feedback([] {
              glNewList(2, GL_COMPILE_AND_EXECUTE);
              glPassThrough(8.0f);
              glEndList();
            }).size(),
            2u);
  EXPECT_TRUE(Feedback([] {
                glNewList(3, GL_COMPILE);
                glPassThrough(9.0f);
                glEndList();
              }).empty());
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, RasterPosIsCompiled) {
  glNewList(1, GL_COMPILE);
  glRasterPos2f(0.5f, 0.5f);
  glEndList();
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_RASTER_POSITION)[0], 0.0f);
  glCallList(1);
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_RASTER_POSITION)[0], 0.75f * kWidth);
  glNewList(2, GL_COMPILE_AND_EXECUTE);
  glRasterPos3i(0, 0, 0);
  glEndList();
  EXPECT_EQ(GetFloats<4>(GL_CURRENT_RASTER_POSITION)[0], 0.5f * kWidth);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, MapPointsAreCopiedAtCompileTime) {
  GLfloat points[2][3] = {{1, 2, 3}, {4, 5, 6}};
  glNewList(1, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, &points[0][0]);
  glMapGrid1f(7, 0, 1);
  glEndList();
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), 1);  // not run
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 1);
  points[1][0] = 40;
  glCallList(1);
  EXPECT_EQ(GetInt(GL_MAP1_GRID_SEGMENTS), 7);
  GLfloat coeff[6] = {};
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, coeff);
  EXPECT_EQ(coeff[3], 4.0f);
  EXPECT_EQ(coeff[5], 6.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, EvaluationsAreCompiledAndRunOnce) {
  static const GLfloat points[2][3] = {{-0.5f, 0, 0}, {0.5f, 0, 0}};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, &points[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(3, 0, 1);
  EXPECT_EQ(Points(Feedback([] {
              glNewList(1, GL_COMPILE);
              glEvalMesh1(GL_POINT, 0, 3);
              glBegin(GL_POINTS);
              glEvalCoord1f(0.5f);
              glEvalPoint1(1);
              glEnd();
              glEndList();
            })),
            0);
  EXPECT_EQ(Points(Feedback([] { glCallList(1); })), 6);
  EXPECT_NO_GL_ERROR();
}

// Mesa compiles the glBegin, glEvalCoord and glEnd that a glEvalMesh issues
// in GL_COMPILE_AND_EXECUTE as well as the glEvalMesh (its exec code calls
// them through the save dispatch): a replay draws the mesh three times.
TEST_F(ListCommandsTest, CompileAndExecuteOfEvalMeshCompilesOnlyTheMesh) {
  GLFX_SKIP_ON_MESA("a glEvalMesh run in GL_COMPILE_AND_EXECUTE compiles what it issues too");
  static const GLfloat points[2][3] = {{-0.5f, 0, 0}, {0.5f, 0, 0}};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, &points[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(3, 0, 1);
  EXPECT_EQ(Points(Feedback([] {
              glNewList(2, GL_COMPILE_AND_EXECUTE);
              glEvalMesh1(GL_POINT, 0, 3);
              glBegin(GL_POINTS);
              glVertex2f(0, 0);
              glEvalCoord1f(0.5f);  // ends the vertex node: the rest are commands
              glVertex2f(0, 0);
              glEnd();
              glEndList();
            })),
            7);
  EXPECT_EQ(Points(Feedback([] { glCallList(2); })), 7);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, ArrayContentsAreCapturedAtCompileTime) {
  static GLfloat v[3][2] = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0, 0.5f}};
  static const GLubyte indices[2] = {2, 0};
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEnableClientState(GL_VERTEX_ARRAY);
  EXPECT_TRUE(Feedback([] {
                glNewList(1, GL_COMPILE);
                glDrawArrays(GL_POINTS, 0, 3);
                glDrawElements(GL_POINTS, 2, GL_UNSIGNED_BYTE, indices);
                glEndList();
              }).empty());
  v[0][0] = 0.25f;
  glDisableClientState(GL_VERTEX_ARRAY);  // the replay does not read the arrays
  const std::vector<GLfloat> f = Feedback([] { glCallList(1); });
  ASSERT_EQ(Points(f), 5);
  // Window x = (x + 1) * width / 2: -0.5 as compiled, not the 0.25 since.
  EXPECT_EQ(f[1], 0.5f * kWidth / 2);
  EXPECT_EQ(f[4 * 3 + 1], 1.0f * kWidth / 2);  // element 2 through the indices
  EXPECT_EQ(f[4 * 4 + 1], 0.5f * kWidth / 2);
  v[0][0] = 0.0f;
  glEnableClientState(GL_VERTEX_ARRAY);
  EXPECT_EQ(Points(Feedback([] {
              glNewList(2, GL_COMPILE_AND_EXECUTE);
              glDrawArrays(GL_POINTS, 0, 3);
              glEndList();
            })),
            3);
  EXPECT_NO_GL_ERROR();
}

// GL 2.1 §5.4: the error of a compiled command is raised when the list runs.
// (Not GL_POLYGON + 1 as the bad mode: that is GL_LINES_ADJACENCY, which
// Mesa's compatibility context accepts.)
TEST_F(ListCommandsTest, ArrayDrawErrorsAreCompiled) {
  static const GLfloat v[2] = {0, 0};
  glVertexPointer(2, GL_FLOAT, 0, v);
  glEnableClientState(GL_VERTEX_ARRAY);
  glNewList(1, GL_COMPILE);
  glDrawArrays(0x7fff, 0, 1);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glNewList(2, GL_COMPILE);
  glDrawElements(GL_POINTS, -1, GL_UNSIGNED_BYTE, nullptr);
  glEndList();
  EXPECT_NO_GL_ERROR();
  glCallList(2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_NO_GL_ERROR();
}

// Mesa's save_DrawArrays begins its primitive with no_current_update: a
// replay leaves the current colour alone, where a glBegin/glEnd with glColor
// makes its last colour current.
TEST_F(ListCommandsTest, ArrayDrawReplayKeepsTheCurrentColor) {
  static const GLfloat v[2][2] = {{0, 0}, {0.5f, 0}};
  static const GLfloat c[2][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}};
  glVertexPointer(2, GL_FLOAT, 0, v);
  glColorPointer(4, GL_FLOAT, 0, c);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glNewList(1, GL_COMPILE);
  glDrawArrays(GL_POINTS, 0, 2);
  glEndList();
  glColor4f(0, 0, 1, 1);
  glCallList(1);
  const std::array<GLfloat, 4> color = GetFloats<4>(GL_CURRENT_COLOR);
  EXPECT_EQ(color[1], 0.0f);
  EXPECT_EQ(color[2], 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ListCommandsTest, ClientStateCommandsAreExecutedAtOnce) {
  static const GLfloat v[2] = {0, 0};
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glNewList(1, GL_COMPILE);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, v);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, 16, nullptr, GL_STATIC_DRAW);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_TRUE);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), static_cast<GLint>(buffer));
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 1);
  GLint size = 0;
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, 16);
  glPopClientAttrib();
  glDisableClientState(GL_VERTEX_ARRAY);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glCallList(1);  // nothing of it was compiled
  EXPECT_EQ(glIsEnabled(GL_VERTEX_ARRAY), GL_FALSE);
  EXPECT_EQ(GetInt(GL_ARRAY_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_CLIENT_ATTRIB_STACK_DEPTH), 0);
  glDeleteBuffers(1, &buffer);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
