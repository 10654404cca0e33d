// Selection and feedback (GL 2.1 §5.2, §5.3): glRenderMode, the name stack,
// glSelectBuffer, glFeedbackBuffer, glPassThrough, their state (tables 6.57,
// 6.58) and every error. Runs against Mesa too. The buffers' contents for
// real scenes are compared with Mesa's by reference/feedback/.
#include "api/gl_test_fixture.h"

namespace {

using glfx_test::GetBool;
using glfx_test::GetInt;

class SelectFeedbackTest : public glfx_test::GLTest {
 protected:
  void SetUp() override {
    GLTest::SetUp();
    // An identity transform over the 64x64 viewport.
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }
  static void triangleAt(float z) {
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.5f, -0.5f, z);
    glVertex3f(0.5f, -0.5f, z);
    glVertex3f(0.0f, 0.5f, z);
    glEnd();
  }
  static void* pointer(GLenum pname) {
    void* p = reinterpret_cast<void*>(0x1234);
    glGetPointerv(pname, &p);
    return p;
  }
  GLuint select_[64] = {};
  GLfloat feedback_[64] = {};
};

TEST_F(SelectFeedbackTest, InitialState) {
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  EXPECT_EQ(GetInt(GL_MAX_NAME_STACK_DEPTH), 64);
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 0);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_SIZE), 0);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_TYPE), GL_2D);
  EXPECT_EQ(pointer(GL_SELECTION_BUFFER_POINTER), nullptr);
  EXPECT_EQ(pointer(GL_FEEDBACK_BUFFER_POINTER), nullptr);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, BuffersAreState) {
  glSelectBuffer(64, select_);
  glFeedbackBuffer(32, GL_3D_COLOR, feedback_);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 64);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_SIZE), 32);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_TYPE), GL_3D_COLOR);
  EXPECT_EQ(pointer(GL_SELECTION_BUFFER_POINTER), select_);
  EXPECT_EQ(pointer(GL_FEEDBACK_BUFFER_POINTER), feedback_);
  for (GLenum type : {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE}) {
    glFeedbackBuffer(8, type, feedback_);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_TYPE), static_cast<GLint>(type));
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(SelectFeedbackTest, RenderModeReturnsHitsAndCounts) {
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);  // leaving GL_RENDER returns 0
  glSelectBuffer(64, select_);
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_SELECT);
  glInitNames();
  glPushName(7);
  triangleAt(0.0f);
  glLoadName(8);
  triangleAt(0.5f);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 1);
  EXPECT_EQ(glRenderMode(GL_RENDER), 2);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);  // leaving GL_SELECT empties the stack
  // Two records of 4 words: 1 name, z1, z2, the name. Window z of z = 0 is 0.5.
  EXPECT_EQ(select_[0], 1u);
  EXPECT_EQ(select_[1], 2147483648u);
  EXPECT_EQ(select_[2], 2147483648u);
  EXPECT_EQ(select_[3], 7u);
  EXPECT_EQ(select_[4], 1u);
  EXPECT_EQ(select_[7], 8u);
  EXPECT_GT(select_[5], 2147483648u);

  glFeedbackBuffer(64, GL_2D, feedback_);
  EXPECT_EQ(glRenderMode(GL_FEEDBACK), 0);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_FEEDBACK);
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), 8);  // token, count, three x y pairs
  EXPECT_EQ(feedback_[0], static_cast<GLfloat>(GL_POLYGON_TOKEN));
  EXPECT_EQ(feedback_[1], 3.0f);
  EXPECT_EQ(feedback_[2], 16.0f);  // (-0.5, -0.5) in a 64x64 viewport
  EXPECT_EQ(feedback_[3], 16.0f);
  EXPECT_EQ(feedback_[4], 48.0f);
  EXPECT_EQ(feedback_[5], 16.0f);
  EXPECT_EQ(feedback_[6], 32.0f);
  EXPECT_EQ(feedback_[7], 48.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, ReenteringAModeReturnsWhatItHeld) {
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_SELECT), 1);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);  // nothing since
  glFeedbackBuffer(64, GL_3D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glPassThrough(5.0f);
  EXPECT_EQ(glRenderMode(GL_FEEDBACK), 2);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, SelectionOverflowReturnsMinusOne) {
  for (GLuint& w : select_) w = 0xdeadbeefu;
  glSelectBuffer(6, select_);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  triangleAt(0.0f);
  glPushName(2);  // closes the first record (4 words), the second needs 5
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
  EXPECT_EQ(select_[0], 1u);
  EXPECT_EQ(select_[3], 1u);
  EXPECT_EQ(select_[4], 2u);           // what fits of the second record is written
  EXPECT_EQ(select_[6], 0xdeadbeefu);  // and nothing past the buffer
  // A record that fits exactly is not an overflow.
  glSelectBuffer(4, select_);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(3);
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, FeedbackOverflowReturnsMinusOne) {
  for (GLfloat& f : feedback_) f = -7.0f;
  glFeedbackBuffer(5, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glPassThrough(1.0f);
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
  EXPECT_EQ(feedback_[0], static_cast<GLfloat>(GL_PASS_THROUGH_TOKEN));
  EXPECT_EQ(feedback_[1], 1.0f);
  EXPECT_EQ(feedback_[2], static_cast<GLfloat>(GL_POLYGON_TOKEN));
  EXPECT_EQ(feedback_[4], 16.0f);
  EXPECT_EQ(feedback_[5], -7.0f);  // nothing past the buffer
  glFeedbackBuffer(4, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glPassThrough(1.0f);
  glPassThrough(2.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), 4);  // exactly full
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, PassThroughOnlyInFeedback) {
  glPassThrough(1.0f);  // GL_RENDER: ignored
  EXPECT_NO_GL_ERROR();
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  glPassThrough(2.0f);  // GL_SELECT: ignored
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  glFeedbackBuffer(64, GL_4D_COLOR_TEXTURE, feedback_);
  glRenderMode(GL_FEEDBACK);
  glPassThrough(3.5f);
  EXPECT_EQ(glRenderMode(GL_RENDER), 2);
  EXPECT_EQ(feedback_[0], static_cast<GLfloat>(GL_PASS_THROUGH_TOKEN));
  EXPECT_EQ(feedback_[1], 3.5f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, NameStackIgnoredOutsideSelect) {
  glPushName(1);
  glPushName(2);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  glPopName();
  glPopName();
  glPopName();    // no underflow: ignored
  glLoadName(3);  // no INVALID_OPERATION: ignored
  glInitNames();
  EXPECT_NO_GL_ERROR();
  glFeedbackBuffer(64, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glPushName(1);
  glLoadName(2);
  glPopName();
  glPopName();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  glRenderMode(GL_RENDER);
}

TEST_F(SelectFeedbackTest, NameStackDepthAndErrors) {
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  glInitNames();
  glLoadName(1);  // §5.2: LoadName with an empty stack
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glPopName();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  for (int i = 0; i < 64; ++i) glPushName(i);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 64);
  glPushName(64);
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 64);
  glPopName();
  glPopName();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 62);
  glLoadName(5);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 62);
  glInitNames();
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 0);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
}

TEST_F(SelectFeedbackTest, BufferCallsRefusedInTheirMode) {
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  GLuint other[4];
  glSelectBuffer(4, other);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 64);
  glFeedbackBuffer(16, GL_3D, feedback_);  // allowed: not in GL_FEEDBACK
  EXPECT_NO_GL_ERROR();
  glRenderMode(GL_FEEDBACK);
  glFeedbackBuffer(8, GL_2D, feedback_);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_SIZE), 16);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_TYPE), GL_3D);
  glSelectBuffer(32, select_);  // allowed: not in GL_SELECT
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 32);
  glRenderMode(GL_RENDER);
}

TEST_F(SelectFeedbackTest, BadArguments) {
  glSelectBuffer(-1, select_);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 0);
  glFeedbackBuffer(-1, GL_2D, feedback_);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFeedbackBuffer(8, GL_RGBA, feedback_);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glFeedbackBuffer(8, GL_4D_COLOR_TEXTURE + 1, feedback_);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_SIZE), 0);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_TYPE), GL_2D);
  glFeedbackBuffer(8, GL_3D, nullptr);  // would be written
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_SIZE), 0);
}

TEST_F(SelectFeedbackTest, RenderModeBadEnum) {
  EXPECT_EQ(glRenderMode(GL_RGBA), 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);
  glFeedbackBuffer(64, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  EXPECT_EQ(glRenderMode(GL_POLYGON), 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_FEEDBACK);
  glRenderMode(GL_RENDER);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, ModeBeforeItsBuffer) {
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_EQ(glRenderMode(GL_FEEDBACK), 0);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, RefusedModeChangeIsIgnored) {
  GLFX_SKIP_ON_MESA(
      "glRenderMode(GL_SELECT) before glSelectBuffer records the error and enters GL_SELECT anyway");
  glRenderMode(GL_SELECT);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);  // §2.5: the command is ignored
  glRenderMode(GL_FEEDBACK);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);
}

TEST_F(SelectFeedbackTest, RenderModeBadEnumKeepsTheHits) {
  GLFX_SKIP_ON_MESA(
      "glRenderMode(bad enum) in GL_SELECT first empties the selection buffer, then records the error");
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_RGBA), 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 1);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
}

TEST_F(SelectFeedbackTest, NullSelectBufferWithRoomIsRefused) {
  GLFX_SKIP_ON_MESA("glSelectBuffer(4, NULL) is accepted, and the first hit record writes through NULL");
  glSelectBuffer(4, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 0);
  glSelectBuffer(0, nullptr);  // an empty buffer: allowed, it overflows at the first record
  EXPECT_NO_GL_ERROR();
  glRenderMode(GL_SELECT);
  glInitNames();
  triangleAt(0.0f);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);
}

TEST_F(SelectFeedbackTest, RefusedBetweenBeginAndEnd) {
  glSelectBuffer(64, select_);
  glFeedbackBuffer(64, GL_2D, feedback_);
  struct Case {
    const char* name;
    void (*call)();
  };
  const Case cases[] = {
      {"glRenderMode", [] { EXPECT_EQ(glRenderMode(GL_SELECT), 0); }},
      {"glSelectBuffer",
       [] {
         static GLuint b[4];
         glSelectBuffer(4, b);
       }},
      {"glFeedbackBuffer",
       [] {
         static GLfloat b[4];
         glFeedbackBuffer(4, GL_3D, b);
       }},
      {"glInitNames", [] { glInitNames(); }},
      {"glPushName", [] { glPushName(1); }},
      {"glPopName", [] { glPopName(); }},
      {"glLoadName", [] { glLoadName(1); }},
      {"glPassThrough", [] { glPassThrough(1.0f); }},
  };
  for (const Case& c : cases) {
    glBegin(GL_TRIANGLES);
    c.call();
    glEnd();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << c.name;
  }
  EXPECT_EQ(GetInt(GL_RENDER_MODE), GL_RENDER);
  EXPECT_EQ(GetInt(GL_SELECTION_BUFFER_SIZE), 64);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_SIZE), 64);
  EXPECT_EQ(GetInt(GL_FEEDBACK_BUFFER_TYPE), GL_2D);
  // In GL_SELECT too: the name stack does not change.
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glBegin(GL_POINTS);
  glPushName(2);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_NAME_STACK_DEPTH), 1);
  glRenderMode(GL_RENDER);
}

TEST_F(SelectFeedbackTest, NothingIsRasterizedInSelectOrFeedback) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  triangleAt(0.0f);
  glRenderMode(GL_RENDER);
  glFeedbackBuffer(64, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  triangleAt(0.0f);
  glRenderMode(GL_RENDER);
  const unsigned char* p = pixels();
  int lit = 0;
  for (int i = 0; i < glfx_test::kWidth * glfx_test::kHeight * 4; ++i) lit += p[i] != 0;
  EXPECT_EQ(lit, 0);
  triangleAt(0.0f);  // GL_RENDER again: drawn
  p = pixels();
  for (int i = 0; i < glfx_test::kWidth * glfx_test::kHeight * 4; ++i) lit += p[i] != 0;
  EXPECT_GT(lit, 0);
}

// ---- the raster position and the pixel tokens (§2.13, §5.3) ----------------

TEST_F(SelectFeedbackTest, RasterPositionState) {
  EXPECT_EQ(GetBool(GL_CURRENT_RASTER_POSITION_VALID), GL_TRUE);
  auto p = glfx_test::GetFloats<4>(GL_CURRENT_RASTER_POSITION);
  EXPECT_EQ(p, (std::array<GLfloat, 4>{0, 0, 0, 1}));
  glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
  glRasterPos2f(0.5f, -0.5f);  // identity transform, 64x64 viewport
  p = glfx_test::GetFloats<4>(GL_CURRENT_RASTER_POSITION);
  EXPECT_EQ(p, (std::array<GLfloat, 4>{48, 16, 0.5f, 1}));
  EXPECT_EQ(glfx_test::GetFloats<4>(GL_CURRENT_RASTER_COLOR),
            (std::array<GLfloat, 4>{0.25f, 0.5f, 0.75f, 1.0f}));
  EXPECT_FLOAT_EQ(glfx_test::GetFloat(GL_CURRENT_RASTER_DISTANCE), std::sqrt(0.5f));
  glRasterPos3f(0.0f, 0.0f, 2.0f);  // beyond the far plane
  EXPECT_EQ(GetBool(GL_CURRENT_RASTER_POSITION_VALID), GL_FALSE);
  glRasterPos4i(0, 0, 0, 1);
  EXPECT_EQ(GetBool(GL_CURRENT_RASTER_POSITION_VALID), GL_TRUE);
  glBegin(GL_POINTS);
  glRasterPos2i(1, 1);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glfx_test::GetFloats<4>(GL_CURRENT_RASTER_POSITION), (std::array<GLfloat, 4>{32, 32, 0.5f, 1}));
}

TEST_F(SelectFeedbackTest, PixelTokens) {
  static const GLubyte bits[8] = {};
  glFeedbackBuffer(64, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glRasterPos2f(0.5f, -0.5f);
  glBitmap(8, 8, 0, 0, 2.0f, 3.0f, bits);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glRasterPos3f(0.0f, 0.0f, 2.0f);  // invalid: nothing is fed back
  glBitmap(8, 8, 0, 0, 2.0f, 3.0f, bits);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  EXPECT_EQ(glRenderMode(GL_RENDER), 9);
  EXPECT_EQ(feedback_[0], static_cast<GLfloat>(GL_BITMAP_TOKEN));
  EXPECT_EQ(feedback_[1], 48.0f);
  EXPECT_EQ(feedback_[3], static_cast<GLfloat>(GL_DRAW_PIXEL_TOKEN));
  EXPECT_EQ(feedback_[4], 50.0f);  // moved by the bitmap
  EXPECT_EQ(feedback_[5], 19.0f);
  EXPECT_EQ(feedback_[6], static_cast<GLfloat>(GL_COPY_PIXEL_TOKEN));
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, RasterPositionIsAHitPixelsAreNot) {
  static const GLubyte bits[8] = {};
  glSelectBuffer(64, select_);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(1);
  glBitmap(8, 8, 0, 0, 2.0f, 3.0f, bits);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glLoadName(2);
  glRasterPos3f(0.0f, 0.0f, 0.5f);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(select_[1], 3221225472u);  // window z 0.75
  EXPECT_EQ(select_[3], 2u);
  EXPECT_NO_GL_ERROR();
}

TEST_F(SelectFeedbackTest, PixelCommandErrors) {
  static const GLubyte bits[64] = {};
  glFeedbackBuffer(64, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glBitmap(-1, 8, 0, 0, 0, 0, bits);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawPixels(1, -1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDrawPixels(1, 1, GL_RGBA8, GL_UNSIGNED_BYTE, bits);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_RGBA, bits);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, bits);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, bits);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_INT_8_8_8_8, bits);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, bits);  // no stencil buffer
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyPixels(0, 0, -1, 1, GL_COLOR);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyPixels(0, 0, 1, 1, GL_RGBA);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glBitmap(0, 0, 0, 0, 0, 0, bits);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bits);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBegin(GL_POINTS);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);  // nothing fed back
  // Valid pixel formats raise nothing.
  glFeedbackBuffer(64, GL_2D, feedback_);
  glRenderMode(GL_FEEDBACK);
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, bits);
  glDrawPixels(1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, bits);
  glDrawPixels(1, 1, GL_LUMINANCE_ALPHA, GL_SHORT, bits);
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, bits);
  glDrawPixels(1, 1, GL_COLOR_INDEX, GL_BITMAP, bits);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glRenderMode(GL_RENDER), 18);
}

TEST_F(SelectFeedbackTest, EmptyBitmapMovesTheRasterPositionWhenRendering) {
  glRasterPos2f(0.0f, 0.0f);
  glBitmap(0, 0, 0, 0, 3.5f, -2.0f, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glfx_test::GetFloats<4>(GL_CURRENT_RASTER_POSITION),
            (std::array<GLfloat, 4>{35.5f, 30, 0.5f, 1}));
}

}  // namespace
