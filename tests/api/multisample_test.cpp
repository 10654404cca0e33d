// Multisample state (GL 2.1 §3.2.1, §4.1.3; ARB_multisample): glSampleCoverage,
// the GL_MULTISAMPLE and GL_SAMPLE_* enables, their attribute group and
// display lists; on a surface without sample buffers they change nothing
// drawn. Built against Mesa too: every expectation was measured on Mesa 22.3.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using MultisampleTest = GLTest;

float CoverageValue() {
  GLfloat v = -1;
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &v);
  return v;
}

TEST_F(MultisampleTest, SampleCoverageIsClampedAndKeptAsGiven) {
  EXPECT_EQ(GetInt(GL_SAMPLE_BUFFERS), 0);
  EXPECT_EQ(GetInt(GL_SAMPLES), 0);
  EXPECT_EQ(CoverageValue(), 1.0f);
  glSampleCoverage(2.5f, GL_TRUE);
  EXPECT_EQ(CoverageValue(), 1.0f);
  EXPECT_EQ(GetInt(GL_SAMPLE_COVERAGE_INVERT), 1);
  glSampleCoverage(-1.0f, 7);
  EXPECT_EQ(CoverageValue(), 0.0f);
  EXPECT_EQ(GetInt(GL_SAMPLE_COVERAGE_INVERT), 7);  // not made 0 or 1
  glSampleCoverage(0.375f, GL_FALSE);
  EXPECT_EQ(CoverageValue(), 0.375f);
  glSampleCoverage(std::nanf(""), GL_FALSE);
  EXPECT_EQ(CoverageValue(), 0.0f);
  EXPECT_NO_GL_ERROR();
  glBegin(GL_POINTS);
  glSampleCoverage(0.5f, GL_FALSE);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(CoverageValue(), 0.0f);
}

TEST_F(MultisampleTest, StateIsPushedAndCompiled) {
  glSampleCoverage(0.25f, GL_TRUE);
  glEnable(GL_SAMPLE_COVERAGE);
  glPushAttrib(GL_MULTISAMPLE_BIT);
  glSampleCoverage(0.75f, GL_FALSE);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_SAMPLE_COVERAGE);
  glPopAttrib();
  EXPECT_EQ(CoverageValue(), 0.25f);
  EXPECT_EQ(GetInt(GL_SAMPLE_COVERAGE_INVERT), 1);
  EXPECT_EQ(glIsEnabled(GL_MULTISAMPLE), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_SAMPLE_COVERAGE), GL_TRUE);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glSampleCoverage(0.5f, GL_FALSE);
  glEndList();
  EXPECT_EQ(CoverageValue(), 0.25f);
  glCallList(list);
  EXPECT_EQ(CoverageValue(), 0.5f);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(MultisampleTest, EnablesChangeNothingWithoutSampleBuffers) {
  for (GLenum cap : {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE}) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE);
  }
  EXPECT_NO_GL_ERROR();
  glSampleCoverage(0.0f, GL_FALSE);
  glColor4f(1, 0, 0, 0.3f);
  glRectf(-1, -1, 1, 1);
  GLubyte p[4] = {};
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(p[0], 255);
  EXPECT_EQ(p[1], 0);
  EXPECT_EQ(p[3], 76);  // alpha neither made one nor turned into coverage
}

}  // namespace
}  // namespace glfx_test
