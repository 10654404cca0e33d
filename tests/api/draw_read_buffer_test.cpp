// glDrawBuffer and glReadBuffer (GL 2.1 §4.2.1, §4.3.2) on an OSMesa context,
// a single-buffered surface: Mesa's rules (buffers.c) for names that do not
// exist there, and drawing and reading after each choice.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using DrawReadBufferTest = GLTest;

TEST_F(DrawReadBufferTest, StartsAsTheFrontBuffer) {
  GLint draw = 0, read = 0, doubleBuffered = -1;
  glGetIntegerv(GL_DRAW_BUFFER, &draw);
  glGetIntegerv(GL_READ_BUFFER, &read);
  glGetIntegerv(GL_DOUBLEBUFFER, &doubleBuffered);
  EXPECT_EQ(draw, GL_FRONT);
  EXPECT_EQ(read, GL_FRONT);
  EXPECT_EQ(doubleBuffered, 0);
  EXPECT_NO_GL_ERROR();
}

// On a single-buffered surface the back buffer is the front one, and the
// name is kept as given.
TEST_F(DrawReadBufferTest, BackIsTheFrontOfASingleBufferedSurface) {
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_BACK);
  EXPECT_NO_GL_ERROR();
  GLint draw = 0, read = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw);
  glGetIntegerv(GL_READ_BUFFER, &read);
  EXPECT_EQ(draw, GL_BACK);
  EXPECT_EQ(read, GL_BACK);
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  unsigned char out[4] = {0, 0, 0, 0};
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 51);
  EXPECT_EQ(out[3], 204);
  EXPECT_EQ(pixels()[0], 51);
}

TEST_F(DrawReadBufferTest, MissingBuffersAreInvalidOperations) {
  const GLenum missing[] = {GL_RIGHT, GL_FRONT_RIGHT, GL_BACK_RIGHT, GL_AUX0, GL_AUX3, 0x8CE0 /* COLOR_ATTACHMENT0 */};
  for (GLenum b : missing) {
    glDrawBuffer(b);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION) << "glDrawBuffer 0x" << std::hex << b;
    glReadBuffer(b);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION) << "glReadBuffer 0x" << std::hex << b;
  }
  glDrawBuffer(GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glReadBuffer(GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLint draw = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &draw);
  EXPECT_EQ(draw, GL_FRONT);
}

TEST_F(DrawReadBufferTest, NoneDrawsNothingButDepthIsStillCleared) {
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_NONE);
  EXPECT_NO_GL_ERROR();
  glClearColor(0, 1, 0, 1);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1, -1);
  glVertex2f(3, -1);
  glVertex2f(-1, 3);
  glEnd();
  glFinish();
  EXPECT_EQ(pixels()[0], 255);
  EXPECT_EQ(pixels()[1], 0);
  float depth = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.5f, 1e-6f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DrawReadBufferTest, ReadFromNoneIsAnInvalidOperation) {
  glReadBuffer(GL_NONE);
  EXPECT_NO_GL_ERROR();
  unsigned char out[4] = {7, 7, 7, 7};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(out[0], 7);
}

TEST_F(DrawReadBufferTest, PopAttribRestoresTheDrawBuffer) {
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_NONE);
  glPopAttrib();
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(pixels()[2], 255);
  EXPECT_NO_GL_ERROR();
}

TEST_F(DrawReadBufferTest, InsideBeginEndIsAnInvalidOperation) {
  glBegin(GL_POINTS);
  glDrawBuffer(GL_FRONT);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glReadBuffer(GL_FRONT);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

}  // namespace
}  // namespace glfx_test
