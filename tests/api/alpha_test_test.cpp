// The alpha test of GL 2.1 §4.1.4: glAlphaFunc, GL_ALPHA_TEST, their queries,
// errors, attribute groups and display lists, and what it discards.
#include <cmath>
#include <limits>

#include "gl_test_fixture.h"

using namespace glfx_test;

namespace {

class AlphaTestTest : public GLTest {
 protected:
  // A quad over the whole buffer of colour (1, 0, 0, alpha); returns the red
  // byte of the centre pixel (0 where the quad was discarded).
  int drawAndReadRed(float alpha) {
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 0, 0, alpha);
    glRectf(-1, -1, 1, 1);
    return pixels()[4 * (kWidth * (kHeight / 2) + kWidth / 2)];
  }
};

const GLenum kFuncs[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                         GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

TEST_F(AlphaTestTest, Defaults) {
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_FALSE);
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(AlphaTestTest, EveryFunctionIsStoredAndQueried) {
  for (GLenum f : kFuncs) {
    glAlphaFunc(f, 0.25f);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), static_cast<GLint>(f));
    EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.25f);
  }
  glEnable(GL_ALPHA_TEST);
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_TRUE);
  EXPECT_EQ(GetBool(GL_ALPHA_TEST), GL_TRUE);
  glDisable(GL_ALPHA_TEST);
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(AlphaTestTest, ReferenceIsClamped) {
  glAlphaFunc(GL_LESS, 1.5f);
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 1.0f);
  glAlphaFunc(GL_LESS, -0.5f);
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.0f);
  glAlphaFunc(GL_LESS, std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.0f);
  glAlphaFunc(GL_LESS, 1.0f);
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_REF), 0x7fffffff);  // a normalized value as an integer
  EXPECT_NO_GL_ERROR();
}

TEST_F(AlphaTestTest, BadFunctionIsRefusedAndChangesNothing) {
  glAlphaFunc(GL_GREATER, 0.5f);
  glAlphaFunc(GL_NEVER - 1, 0.25f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glAlphaFunc(GL_ALWAYS + 1, 0.25f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glAlphaFunc(GL_FRONT, 0.25f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_GREATER);
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.5f);
}

TEST_F(AlphaTestTest, InsideBeginEndIsAnInvalidOperation) {
  glBegin(GL_TRIANGLES);
  glAlphaFunc(GL_LESS, 0.5f);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_ALWAYS);
}

TEST_F(AlphaTestTest, PushAndPopColorBufferAndEnableBits) {
  glAlphaFunc(GL_LEQUAL, 0.75f);
  glEnable(GL_ALPHA_TEST);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glAlphaFunc(GL_NEVER, 0.1f);
  glDisable(GL_ALPHA_TEST);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_LEQUAL);
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.75f);
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_TRUE);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_ALPHA_TEST);
  glAlphaFunc(GL_NEVER, 0.1f);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_TRUE);
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_NEVER);  // not in GL_ENABLE_BIT
  EXPECT_NO_GL_ERROR();
}

TEST_F(AlphaTestTest, DisplayListRecordsTheFunction) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glAlphaFunc(GL_GEQUAL, 0.5f);
  glEnable(GL_ALPHA_TEST);
  glEndList();
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_ALWAYS);  // compiled, not run
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_FALSE);
  glCallList(list);
  EXPECT_EQ(GetInt(GL_ALPHA_TEST_FUNC), GL_GEQUAL);
  EXPECT_EQ(GetFloat(GL_ALPHA_TEST_REF), 0.5f);
  EXPECT_EQ(glIsEnabled(GL_ALPHA_TEST), GL_TRUE);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(AlphaTestTest, DiscardsByFunction) {
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_LESS, 0.5f);
  EXPECT_EQ(drawAndReadRed(0.25f), 255);
  EXPECT_EQ(drawAndReadRed(0.75f), 0);
  glAlphaFunc(GL_GREATER, 0.5f);
  EXPECT_EQ(drawAndReadRed(0.25f), 0);
  EXPECT_EQ(drawAndReadRed(0.75f), 255);
  glAlphaFunc(GL_NEVER, 0.5f);
  EXPECT_EQ(drawAndReadRed(0.75f), 0);
  glDisable(GL_ALPHA_TEST);
  EXPECT_EQ(drawAndReadRed(0.75f), 255);  // disabled: nothing discarded
  EXPECT_NO_GL_ERROR();
}

// llvmpipe compares the alpha and the reference as the bytes an 8-bit
// colour buffer holds: 0.5 and 0.5 + 0.4 / 255 are both 128, so EQUAL passes
// and GREATER fails.
TEST_F(AlphaTestTest, EightBitBufferComparesBytes) {
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_EQUAL, 0.5f);
  EXPECT_EQ(drawAndReadRed(0.5f + 0.4f / 255.0f), 255);
  glAlphaFunc(GL_GREATER, 0.5f);
  EXPECT_EQ(drawAndReadRed(0.5f + 0.4f / 255.0f), 0);
  EXPECT_NO_GL_ERROR();
}

// A discarded fragment writes no depth (the depth test runs after the alpha test).
TEST_F(AlphaTestTest, DiscardedFragmentsWriteNoDepth) {
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glColor4f(0, 1, 0, 0.25f);
  glBegin(GL_QUADS);  // in front, discarded
  glVertex3f(-1, -1, -0.5f);
  glVertex3f(1, -1, -0.5f);
  glVertex3f(1, 1, -0.5f);
  glVertex3f(-1, 1, -0.5f);
  glEnd();
  glDisable(GL_ALPHA_TEST);
  glColor4f(1, 0, 0, 1);
  glBegin(GL_QUADS);  // behind: passes the depth test only if nothing was written
  glVertex3f(-1, -1, 0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(1, 1, 0.5f);
  glVertex3f(-1, 1, 0.5f);
  glEnd();
  EXPECT_EQ(pixels()[4 * (kWidth * (kHeight / 2) + kWidth / 2)], 255);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
