// glMultiDrawArrays (GL 2.1 §2.8) is the sequence of its glDrawArrays: a
// draw of count 0 draws nothing and leaves the others alone. Mesa 22.3 drops
// the whole multi-draw when the first count is 0 (MESA_FACTS.md, "Vertex
// arrays"; found by the scene fuzz_command_layer).
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using MultiDrawTest = GLTest;

// Two triangles: the first covers the centre, the second only the lower left.
const GLfloat kVerts[] = {-0.8f, -0.8f, 0.8f, -0.8f, 0.0f, 0.8f, -1.0f, -1.0f, -0.6f, -1.0f, -1.0f, -0.6f};

bool CentreDrawn(const unsigned char* p) { return p[(32 * kWidth + 32) * 4 + 0] == 255; }

void DrawWith(const GLint* first, const GLsizei* count, GLsizei n) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, kVerts);
  glColor4f(1, 0, 0, 1);
  glMultiDrawArrays(GL_TRIANGLES, first, count, n);
}

// Counts of 0 after the first, and an incomplete first draw: every draw is
// made, on Mesa as on libglfixed.
TEST_F(MultiDrawTest, ZeroCountsAfterTheFirstDrawTheOthers) {
  const GLint first[3] = {3, 0, 0};
  const GLsizei count[3] = {3, 0, 3};
  DrawWith(first, count, 3);
  ASSERT_NO_GL_ERROR();
  EXPECT_TRUE(CentreDrawn(pixels()));
  const GLint first2[2] = {0, 0};
  const GLsizei count2[2] = {2, 3};
  DrawWith(first2, count2, 2);
  ASSERT_NO_GL_ERROR();
  EXPECT_TRUE(CentreDrawn(pixels()));
}

TEST_F(MultiDrawTest, FirstCountZeroDrawsTheOthers) {
  GLFX_SKIP_ON_MESA("a glMultiDrawArrays whose first count is 0 draws nothing");
  const GLint first[3] = {0, 0, 0};
  const GLsizei count[3] = {0, 0, 3};
  DrawWith(first, count, 3);
  ASSERT_NO_GL_ERROR();
  EXPECT_TRUE(CentreDrawn(pixels()));
}

}  // namespace
}  // namespace glfx_test
