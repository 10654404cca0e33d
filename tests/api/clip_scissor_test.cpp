// User clip planes (GL 2.1 §2.12) and the scissor test (§4.1.2): glClipPlane,
// glGetClipPlane, GL_CLIP_PLANEi, glScissor, GL_SCISSOR_TEST, GL_SCISSOR_BOX,
// their errors, attribute groups and display lists, and what they do to
// drawing and to glClear (with the colour and depth masks).
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using ClipScissorTest = GLTest;

std::array<GLdouble, 4> ClipPlane(GLenum plane) {
  std::array<GLdouble, 4> e;
  e.fill(-12345.0);
  glGetClipPlane(plane, e.data());
  return e;
}

// The RGBA of pixel (x, y), y up (the fixture's buffer is OSMESA_Y_UP).
std::array<int, 4> PixelAt(const unsigned char* p, int x, int y) {
  const unsigned char* q = p + 4 * (y * kWidth + x);
  return {q[0], q[1], q[2], q[3]};
}

// A white quad over the whole viewport, identity matrices.
void FullQuad(float z = 0.0f) {
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, z);
  glVertex3f(1, -1, z);
  glVertex3f(1, 1, z);
  glVertex3f(-1, 1, z);
  glEnd();
}

// ---- glClipPlane -----------------------------------------------------------

TEST_F(ClipScissorTest, EightClipPlanes) {
  EXPECT_EQ(GetInt(GL_MAX_CLIP_PLANES), 8);
  for (int i = 0; i < 8; ++i) {
    const GLenum plane = GL_CLIP_PLANE0 + i;
    SCOPED_TRACE(i);
    EXPECT_EQ(glIsEnabled(plane), GL_FALSE);
    EXPECT_EQ(ClipPlane(plane), (std::array<GLdouble, 4>{0, 0, 0, 0}));
    glEnable(plane);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(glIsEnabled(plane), GL_TRUE);
    EXPECT_EQ(GetBool(plane), GL_TRUE);
    for (int j = 0; j < 8; ++j)
      if (j != i) EXPECT_EQ(glIsEnabled(GL_CLIP_PLANE0 + j), GL_FALSE) << j;
    glDisable(plane);
    EXPECT_EQ(glIsEnabled(plane), GL_FALSE);
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClipScissorTest, PlaneEnumsOutsideTheRangeAreErrors) {
  const GLdouble eq[4] = {1, 2, 3, 4};
  for (GLenum bad : {GLenum(GL_CLIP_PLANE0 + 8), GLenum(GL_CLIP_PLANE0 - 1), GLenum(GL_CLIP_PLANE0 + 16)}) {
    SCOPED_TRACE(bad);
    glClipPlane(bad, eq);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    GLdouble out[4] = {7, 7, 7, 7};
    glGetClipPlane(bad, out);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
    EXPECT_EQ(out[0], 7);
    glEnable(bad);
    EXPECT_GL_ERROR(GL_INVALID_ENUM);
  }
  EXPECT_EQ(ClipPlane(GL_CLIP_PLANE0), (std::array<GLdouble, 4>{0, 0, 0, 0}));
}

// §2.12: the plane is multiplied by the inverse of the modelview matrix in
// effect when glClipPlane is called; later matrix changes leave it alone.
TEST_F(ClipScissorTest, PlaneIsStoredInEyeSpace) {
  const GLdouble eq[4] = {1, 0, 0, 0};
  glTranslatef(1, 2, 3);
  glClipPlane(GL_CLIP_PLANE1, eq);
  EXPECT_EQ(ClipPlane(GL_CLIP_PLANE1), (std::array<GLdouble, 4>{1, 0, 0, -1}));
  glLoadIdentity();
  glScalef(2, 4, 8);
  const GLdouble eq2[4] = {1, 1, 1, 1};
  glClipPlane(GL_CLIP_PLANE2, eq2);
  EXPECT_EQ(ClipPlane(GL_CLIP_PLANE2), (std::array<GLdouble, 4>{0.5, 0.25, 0.125, 1}));
  EXPECT_EQ(ClipPlane(GL_CLIP_PLANE1), (std::array<GLdouble, 4>{1, 0, 0, -1}));
  // The doubles are kept as floats.
  glLoadIdentity();
  const GLdouble third[4] = {1.0 / 3, 0, 0, 0.1};
  glClipPlane(GL_CLIP_PLANE3, third);
  const auto e = ClipPlane(GL_CLIP_PLANE3);
  EXPECT_EQ(e[0], static_cast<double>(1.0f / 3));
  EXPECT_EQ(e[3], static_cast<double>(0.1f));
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClipScissorTest, ClipPlaneCommandsInsideBeginEndAreErrors) {
  const GLdouble eq[4] = {1, 0, 0, 0};
  glBegin(GL_TRIANGLES);
  glClipPlane(GL_CLIP_PLANE0, eq);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(ClipPlane(GL_CLIP_PLANE0), (std::array<GLdouble, 4>{0, 0, 0, 0}));
  GLdouble out[4] = {7, 7, 7, 7};
  glBegin(GL_TRIANGLES);
  glGetClipPlane(GL_CLIP_PLANE0, out);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(out[0], 7);
}

TEST_F(ClipScissorTest, TransformBitSavesPlanesAndEnables) {
  const GLdouble a[4] = {1, 0, 0, 0}, b[4] = {0, 1, 0, 0};
  glClipPlane((GL_CLIP_PLANE0 + 7), a);
  glEnable((GL_CLIP_PLANE0 + 7));
  glPushAttrib(GL_TRANSFORM_BIT);
  glClipPlane((GL_CLIP_PLANE0 + 7), b);
  glDisable((GL_CLIP_PLANE0 + 7));
  glEnable(GL_CLIP_PLANE4);
  glPopAttrib();
  EXPECT_EQ(ClipPlane((GL_CLIP_PLANE0 + 7)), (std::array<GLdouble, 4>{1, 0, 0, 0}));
  EXPECT_EQ(glIsEnabled((GL_CLIP_PLANE0 + 7)), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_CLIP_PLANE4), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClipScissorTest, EnableBitSavesEnablesNotPlanes) {
  const GLdouble a[4] = {1, 0, 0, 0}, b[4] = {0, 1, 0, 0};
  glClipPlane((GL_CLIP_PLANE0 + 6), a);
  glPushAttrib(GL_ENABLE_BIT);
  glEnable((GL_CLIP_PLANE0 + 6));
  glEnable(GL_SCISSOR_TEST);
  glClipPlane((GL_CLIP_PLANE0 + 6), b);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled((GL_CLIP_PLANE0 + 6)), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
  EXPECT_EQ(ClipPlane((GL_CLIP_PLANE0 + 6)), (std::array<GLdouble, 4>{0, 1, 0, 0}));
  EXPECT_NO_GL_ERROR();
}

// §5.4: glClipPlane is compiled with its equation; the modelview is the one
// in effect when the list executes.
TEST_F(ClipScissorTest, ClipPlaneInADisplayList) {
  GLdouble eq[4] = {1, 0, 0, 0};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClipPlane(GL_CLIP_PLANE0, eq);
  glEnable(GL_CLIP_PLANE0);
  glEndList();
  eq[0] = 5;  // the list holds a copy
  EXPECT_EQ(ClipPlane(GL_CLIP_PLANE0), (std::array<GLdouble, 4>{0, 0, 0, 0}));
  EXPECT_EQ(glIsEnabled(GL_CLIP_PLANE0), GL_FALSE);
  glTranslatef(0, 0, 2);
  glRotatef(90, 0, 0, 1);  // x maps to y: the inverse maps the plane back
  glCallList(list);
  const auto e = ClipPlane(GL_CLIP_PLANE0);
  EXPECT_NEAR(e[0], 0, 1e-6);
  EXPECT_NEAR(e[1], 1, 1e-6);
  EXPECT_NEAR(e[2], 0, 1e-6);
  EXPECT_NEAR(e[3], 0, 1e-6);
  EXPECT_EQ(glIsEnabled(GL_CLIP_PLANE0), GL_TRUE);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

// A point is kept where the plane's value is >= 0 (§2.12): x >= 0 keeps the
// right half of a full-screen quad.
TEST_F(ClipScissorTest, PlaneClipsDrawing) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLdouble rightHalf[4] = {1, 0, 0, 0};
  glClipPlane(GL_CLIP_PLANE3, rightHalf);
  glEnable(GL_CLIP_PLANE3);
  glColor3f(1, 1, 1);
  FullQuad();
  const unsigned char* p = pixels();
  EXPECT_EQ(PixelAt(p, 10, 30), (std::array<int, 4>{0, 0, 0, 0}));
  EXPECT_EQ(PixelAt(p, 31, 30), (std::array<int, 4>{0, 0, 0, 0}));
  EXPECT_EQ(PixelAt(p, 32, 30), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_EQ(PixelAt(p, 60, 5), (std::array<int, 4>{255, 255, 255, 255}));
  // Disabled, the plane clips nothing.
  glDisable(GL_CLIP_PLANE3);
  FullQuad();
  EXPECT_EQ(PixelAt(pixels(), 10, 30), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_NO_GL_ERROR();
}

// Every enabled plane clips: eight planes leave the intersection of their
// half-spaces.
TEST_F(ClipScissorTest, AllEightPlanesClip) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLdouble planes[8][4] = {{1, 0, 0, 0.5},  {-1, 0, 0, 0.5},  {0, 1, 0, 0.5},   {0, -1, 0, 0.5},
                                 {1, 1, 0, 0.75}, {-1, 1, 0, 0.75}, {1, -1, 0, 0.75}, {-1, -1, 0, 0.75}};
  for (int i = 0; i < 8; ++i) {
    glClipPlane(GL_CLIP_PLANE0 + i, planes[i]);
    glEnable(GL_CLIP_PLANE0 + i);
  }
  FullQuad();
  const unsigned char* p = pixels();
  EXPECT_EQ(PixelAt(p, 32, 32)[0], 255);  // the centre
  EXPECT_EQ(PixelAt(p, 10, 32)[0], 0);    // left of x = -0.5
  EXPECT_EQ(PixelAt(p, 32, 54)[0], 0);    // above y = 0.5
  EXPECT_EQ(PixelAt(p, 46, 46)[0], 0);    // a corner cut by x + y <= 0.75
  EXPECT_EQ(PixelAt(p, 44, 34)[0], 255);  // inside the octagon
  EXPECT_NO_GL_ERROR();
}

// A NaN or infinite plane never crashes; the triangles it touches are dropped
// by the clipper (draw_pipe_clip.c discards NaN distances).
TEST_F(ClipScissorTest, NanAndInfinitePlanesDoNotCrash) {
  const GLdouble nanPlane[4] = {NAN, 0, 0, 1};
  const GLdouble infPlane[4] = {INFINITY, 0, 0, 0};
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glClipPlane(GL_CLIP_PLANE0, nanPlane);
  glEnable(GL_CLIP_PLANE0);
  FullQuad();
  EXPECT_EQ(PixelAt(pixels(), 32, 32)[0], 0);
  glDisable(GL_CLIP_PLANE0);
  glClipPlane(GL_CLIP_PLANE1, infPlane);
  glEnable(GL_CLIP_PLANE1);
  FullQuad();
  glRotatef(30, 1, 1, 0);  // a NaN through the inverse modelview too
  glClipPlane(GL_CLIP_PLANE2, nanPlane);
  glEnable(GL_CLIP_PLANE2);
  FullQuad();
  glFinish();
  EXPECT_NO_GL_ERROR();
}

// ---- glScissor ---------------------------------------------------------------

TEST_F(ClipScissorTest, InitialScissorBoxIsTheDrawable) {
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{0, 0, kWidth, kHeight}));
  EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClipScissorTest, ScissorBoxIsStoredAsGiven) {
  glScissor(-5, 7, 100, 3);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{-5, 7, 100, 3}));
  EXPECT_EQ(GetFloats<4>(GL_SCISSOR_BOX), (std::array<GLfloat, 4>{-5, 7, 100, 3}));
  glScissor(1, 2, 0, 0);
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{1, 2, 0, 0}));
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClipScissorTest, NegativeScissorSizeIsAnError) {
  glScissor(1, 2, 3, 4);
  glScissor(0, 0, -1, 4);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glScissor(0, 0, 4, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{1, 2, 3, 4}));
  glBegin(GL_TRIANGLES);
  glScissor(5, 5, 5, 5);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{1, 2, 3, 4}));
}

TEST_F(ClipScissorTest, ScissorBitSavesBoxAndTest) {
  glScissor(1, 2, 3, 4);
  glPushAttrib(GL_SCISSOR_BIT);
  glScissor(5, 6, 7, 8);
  glEnable(GL_SCISSOR_TEST);
  EXPECT_EQ(GetBool(GL_SCISSOR_TEST), GL_TRUE);
  glPopAttrib();
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{1, 2, 3, 4}));
  EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(ClipScissorTest, ScissorInADisplayList) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glScissor(3, 4, 5, 6);
  glEnable(GL_SCISSOR_TEST);
  glEndList();
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{0, 0, kWidth, kHeight}));
  glCallList(list);
  EXPECT_EQ(GetInts<4>(GL_SCISSOR_BOX), (std::array<GLint, 4>{3, 4, 5, 6}));
  EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_TRUE);
  glDeleteLists(list, 1);
  EXPECT_NO_GL_ERROR();
}

// Only pixels inside the box are drawn (§4.1.2); off, the box does nothing.
TEST_F(ClipScissorTest, ScissorLimitsDrawing) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(10, 20, 5, 6);
  FullQuad();  // the test is off
  EXPECT_EQ(PixelAt(pixels(), 0, 0)[0], 255);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  FullQuad();
  const unsigned char* p = pixels();
  int covered = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool inside = x >= 10 && x < 15 && y >= 20 && y < 26;
      EXPECT_EQ(PixelAt(p, x, y)[0], inside ? 255 : 0) << x << "," << y;
      covered += PixelAt(p, x, y)[0] != 0;
    }
  EXPECT_EQ(covered, 30);
  EXPECT_NO_GL_ERROR();
}

// glClear honours the scissor box, and only it (not the viewport).
TEST_F(ClipScissorTest, ScissorLimitsClear) {
  glClearColor(0, 0, 0, 0);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glViewport(0, 0, 8, 8);
  glScissor(-4, 60, 10, 100);
  glEnable(GL_SCISSOR_TEST);
  glClearColor(1, 0.5f, 0.25f, 1);
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const unsigned char* p = pixels();
  EXPECT_EQ(PixelAt(p, 0, 63), (std::array<int, 4>{255, 128, 64, 255}));
  EXPECT_EQ(PixelAt(p, 5, 60), (std::array<int, 4>{255, 128, 64, 255}));
  EXPECT_EQ(PixelAt(p, 6, 60), (std::array<int, 4>{0, 0, 0, 0}));
  EXPECT_EQ(PixelAt(p, 0, 59), (std::array<int, 4>{0, 0, 0, 0}));
  EXPECT_EQ(PixelAt(p, 0, 0), (std::array<int, 4>{0, 0, 0, 0}));
  // The depth cleared inside the box only: a quad at z = 0 (window 0.5)
  // with GL_LESS passes outside it and fails inside.
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 1, 0);
  FullQuad(0.0f);
  p = pixels();
  EXPECT_EQ(PixelAt(p, 0, 63), (std::array<int, 4>{255, 128, 64, 255}));
  EXPECT_EQ(PixelAt(p, 6, 60), (std::array<int, 4>{0, 255, 0, 255}));
  EXPECT_NO_GL_ERROR();
}

// glClear writes only the channels glColorMask lets through, and no depth
// under glDepthMask(GL_FALSE) (§4.2.2, §4.2.3).
TEST_F(ClipScissorTest, ClearHonoursTheMasks) {
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(PixelAt(pixels(), 3, 3), (std::array<int, 4>{255, 102, 255, 204}));
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(PixelAt(pixels(), 3, 3), (std::array<int, 4>{255, 102, 255, 204}));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Depth: cleared to 0.25, then a clear to 1 with the mask off keeps 0.25,
  // so a quad at window z 0.5 fails GL_LESS.
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  glClearDepth(1);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0, 1, 0);
  FullQuad(0.0f);
  EXPECT_EQ(PixelAt(pixels(), 3, 3), (std::array<int, 4>{255, 102, 255, 204}));  // failed the depth test
  EXPECT_NO_GL_ERROR();
}

// Drawing honours the masks too: green masked off, no depth written.
TEST_F(ClipScissorTest, DrawingHonoursTheMasks) {
  glClearColor(0, 0, 0, 0);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_FALSE);
  glColor4f(1, 1, 1, 1);
  FullQuad(0.5f);
  EXPECT_EQ(PixelAt(pixels(), 3, 3), (std::array<int, 4>{255, 0, 255, 255}));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glColor4f(0, 1, 0, 1);
  FullQuad(0.9f);  // behind the first quad, which wrote no depth
  EXPECT_EQ(PixelAt(pixels(), 3, 3), (std::array<int, 4>{0, 255, 0, 255}));
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
