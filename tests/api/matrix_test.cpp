// Matrices and matrix stacks (GL 2.1 §2.11.2), checked through glGetDoublev
// and glGetFloatv against double-precision references written from the spec's
// equations (gl_test_fixture.h).
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

using MatrixTest = GLTest;

const double kA[16] = {1, 2, 3, 0, -4, 5, 0.5, 0, 7, -8, 9, 0, 10, 11, -12, 1};
const double kB[16] = {0.5, 0, 1, 2, 3, -1, 0, 1, 0.25, 4, -2, 0, 6, -7, 8, 2};

TEST_F(MatrixTest, LoadMatrixfRoundTripsExactly) {
  float m[16];
  for (int i = 0; i < 16; ++i) m[i] = static_cast<float>(kA[i]) * 1.1f;
  glLoadMatrixf(m);
  GLfloat f[16];
  glGetFloatv(GL_MODELVIEW_MATRIX, f);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(f[i], m[i]) << "element " << i;  // column-major, as given
  GLdouble d[16];
  glGetDoublev(GL_MODELVIEW_MATRIX, d);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(d[i], static_cast<double>(m[i])) << "element " << i;
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, LoadMatrixd) {
  double m[16];
  for (int i = 0; i < 16; ++i) m[i] = kA[i] / 3.0;
  glLoadMatrixd(m);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(m)));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, LoadIdentityAfterLoad) {
  glLoadMatrixd(kA);
  glLoadIdentity();
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, Identity()));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, MultMatrixPostMultiplies) {
  glLoadMatrixd(kA);
  glMultMatrixd(kB);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(kA) * FromColumnMajor(kB)));
  float bf[16];
  for (int i = 0; i < 16; ++i) bf[i] = static_cast<float>(kB[i]);
  glLoadMatrixd(kB);
  glMultMatrixf(bf);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(kB) * FromColumnMajor(kB)));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, Translate) {
  glTranslatef(1.5f, -2.0f, 3.25f);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, TranslationRef(1.5, -2.0, 3.25)));
  glLoadMatrixd(kA);
  glTranslated(-0.5, 4.0, 0.125);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(kA) * TranslationRef(-0.5, 4.0, 0.125)));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, Scale) {
  glScalef(2.0f, -3.0f, 0.5f);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, ScaleRef(2.0, -3.0, 0.5)));
  glLoadMatrixd(kA);
  glScaled(0.25, 8.0, -1.0);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(kA) * ScaleRef(0.25, 8.0, -1.0)));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, RotateAboutTheAxes) {
  const double angles[] = {0.0, 30.0, -45.0, 90.0, 180.0, 270.0, 370.0};
  const double axes[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (double a : angles)
    for (const auto& ax : axes) {
      SCOPED_TRACE(::testing::Message()
                   << "angle " << a << " axis " << ax[0] << "," << ax[1] << "," << ax[2]);
      glLoadIdentity();
      glRotatef(static_cast<float>(a), static_cast<float>(ax[0]), static_cast<float>(ax[1]),
                static_cast<float>(ax[2]));
      EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, RotationRef(a, ax[0], ax[1], ax[2])));
      glLoadIdentity();
      glRotated(a, ax[0], ax[1], ax[2]);
      EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, RotationRef(a, ax[0], ax[1], ax[2])));
    }
  EXPECT_NO_GL_ERROR();
}

// §2.11.2: the axis need not be of unit length; it is normalised.
TEST_F(MatrixTest, RotateNormalisesTheAxis) {
  const double cases[][4] = {
      {30, 1, 2, 3}, {-72.5, 0.2, -0.3, 0.1}, {135, 5, 5, 0},
      {10, 0, 3, 4}, {90, 100, 0, 0},         {45, 0, 0, 0.01},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::Message() << "angle " << c[0] << " axis " << c[1] << "," << c[2] << "," << c[3]);
    glLoadIdentity();
    glRotatef(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]),
              static_cast<float>(c[3]));
    EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, RotationRef(c[0], c[1], c[2], c[3])));
    glLoadMatrixd(kA);
    glRotated(c[0], c[1], c[2], c[3]);
    EXPECT_TRUE(
        MatrixIs(GL_MODELVIEW_MATRIX, FromColumnMajor(kA) * RotationRef(c[0], c[1], c[2], c[3]), 1e-5));
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, Frustum) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 1, 10);
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, FrustumRef(-1, 1, -1, 1, 1, 10)));
  glLoadIdentity();
  glFrustum(-0.3, 0.7, -0.2, 0.4, 0.5, 100);  // asymmetric
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, FrustumRef(-0.3, 0.7, -0.2, 0.4, 0.5, 100)));
  glLoadMatrixd(kA);
  glFrustum(2, -1, 3, 1, 2, 3);  // reversed l/r, b/t are allowed
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, FromColumnMajor(kA) * FrustumRef(2, -1, 3, 1, 2, 3)));
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, Identity())) << "the modelview matrix is not touched";
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, Ortho) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 64, 0, 64, -1, 1);
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, OrthoRef(0, 64, 0, 64, -1, 1)));
  glLoadIdentity();
  glOrtho(-3, 5, 7, -2, 10, -20);  // any non-degenerate box, negative near included
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, OrthoRef(-3, 5, 7, -2, 10, -20)));
  glLoadMatrixd(kB);
  glOrtho(-1, 1, -2, 2, 0.5, 4);
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, FromColumnMajor(kB) * OrthoRef(-1, 1, -2, 2, 0.5, 4)));
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, Identity())) << "the modelview matrix is not touched";
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, ACompositeTransformMultipliesInCallOrder) {
  glTranslatef(1, 2, 3);
  glRotatef(60, 0, 0, 1);
  glScalef(2, 2, 2);
  glTranslated(-1, 0, 0.5);
  Mat4 expected =
      TranslationRef(1, 2, 3) * RotationRef(60, 0, 0, 1) * ScaleRef(2, 2, 2) * TranslationRef(-1, 0, 0.5);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, expected));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, MatrixModeSelectsTheStack) {
  glMatrixMode(GL_PROJECTION);
  glTranslatef(5, 6, 7);
  glMatrixMode(GL_MODELVIEW);
  glScalef(2, 3, 4);
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, TranslationRef(5, 6, 7)));
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, ScaleRef(2, 3, 4)));
  EXPECT_NO_GL_ERROR();
}

void PushPopOneStack(GLenum mode, GLenum matrix, GLenum depth) {
  glMatrixMode(mode);
  glLoadMatrixd(kA);
  glPushMatrix();
  EXPECT_EQ(GetInt(depth), 2);
  EXPECT_TRUE(MatrixIs(matrix, FromColumnMajor(kA))) << "push copies the top";
  glMultMatrixd(kB);
  glPushMatrix();
  EXPECT_EQ(GetInt(depth), 3);
  glLoadIdentity();
  glTranslatef(1, 1, 1);
  EXPECT_TRUE(MatrixIs(matrix, TranslationRef(1, 1, 1)));
  glPopMatrix();
  EXPECT_EQ(GetInt(depth), 2);
  EXPECT_TRUE(MatrixIs(matrix, FromColumnMajor(kA) * FromColumnMajor(kB)));
  glPopMatrix();
  EXPECT_EQ(GetInt(depth), 1);
  EXPECT_TRUE(MatrixIs(matrix, FromColumnMajor(kA)));
  EXPECT_NO_GL_ERROR();
}

TEST_F(MatrixTest, PushPopModelview) {
  PushPopOneStack(GL_MODELVIEW, GL_MODELVIEW_MATRIX, GL_MODELVIEW_STACK_DEPTH);
  EXPECT_EQ(GetInt(GL_PROJECTION_STACK_DEPTH), 1);
  EXPECT_TRUE(MatrixIs(GL_PROJECTION_MATRIX, Identity()));
}

TEST_F(MatrixTest, PushPopProjection) {
  PushPopOneStack(GL_PROJECTION, GL_PROJECTION_MATRIX, GL_PROJECTION_STACK_DEPTH);
  EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 1);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, Identity()));
}

TEST_F(MatrixTest, StacksAreIndependent) {
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glPushMatrix();
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 3);
  EXPECT_EQ(GetInt(GL_PROJECTION_STACK_DEPTH), 2);
  glPopMatrix();
  EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 3);
  EXPECT_EQ(GetInt(GL_PROJECTION_STACK_DEPTH), 1);
  EXPECT_NO_GL_ERROR();
}

// §2.11.2: pushing a full stack is GL_STACK_OVERFLOW and popping a stack of
// one matrix GL_STACK_UNDERFLOW; neither changes the stack. The stack starts
// at depth 1, so with GL_MAX_*_STACK_DEPTH 32 the 31st push fills it and the
// 32nd overflows.
void OverflowAndUnderflow(GLenum mode, GLenum matrix, GLenum depth, GLenum maxDepth) {
  glMatrixMode(mode);
  const GLint max = GetInt(maxDepth);
  ASSERT_EQ(max, 32);
  for (int i = 1; i < max; ++i) {
    glTranslatef(1, 0, 0);
    glPushMatrix();
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "push " << i;
  }
  EXPECT_EQ(GetInt(depth), max);
  glLoadMatrixd(kA);
  glPushMatrix();
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  EXPECT_EQ(GetInt(depth), max) << "overflow leaves the depth";
  EXPECT_TRUE(MatrixIs(matrix, FromColumnMajor(kA))) << "overflow leaves the top matrix";
  glPopMatrix();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(depth), max - 1);
  EXPECT_TRUE(MatrixIs(matrix, TranslationRef(max - 1, 0, 0))) << "the matrices below are intact";
  for (int i = 2; i < max; ++i) glPopMatrix();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(depth), 1);
  EXPECT_TRUE(MatrixIs(matrix, TranslationRef(1, 0, 0)));
  glPopMatrix();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  EXPECT_EQ(GetInt(depth), 1) << "underflow leaves the depth";
  EXPECT_TRUE(MatrixIs(matrix, TranslationRef(1, 0, 0))) << "underflow leaves the matrix";
  glPopMatrix();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  glPushMatrix();  // the stack still works
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(depth), 2);
}

TEST_F(MatrixTest, ModelviewOverflowAndUnderflow) {
  OverflowAndUnderflow(GL_MODELVIEW, GL_MODELVIEW_MATRIX, GL_MODELVIEW_STACK_DEPTH,
                       GL_MAX_MODELVIEW_STACK_DEPTH);
  EXPECT_EQ(GetInt(GL_PROJECTION_STACK_DEPTH), 1);
}

TEST_F(MatrixTest, ProjectionOverflowAndUnderflow) {
  OverflowAndUnderflow(GL_PROJECTION, GL_PROJECTION_MATRIX, GL_PROJECTION_STACK_DEPTH,
                       GL_MAX_PROJECTION_STACK_DEPTH);
  EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 1);
}

TEST_F(MatrixTest, MatricesAreIdentityInANewContext) {
  glTranslatef(1, 2, 3);
  glPushMatrix();
  ScopedContext other(OSMESA_RGBA, 24, 8, 8, 4);
  ASSERT_TRUE(other.makeCurrent());
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, Identity()));
  EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 1);
  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_TRUE(MatrixIs(GL_MODELVIEW_MATRIX, TranslationRef(1, 2, 3)));
  EXPECT_EQ(GetInt(GL_MODELVIEW_STACK_DEPTH), 2);
}

}  // namespace
}  // namespace glfx_test
