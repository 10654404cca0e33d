// The texture matrix stacks (GL 2.1 §2.11.2, table 6.5): one per texture
// unit, addressed by glMatrixMode(GL_TEXTURE) and glActiveTexture, their
// queries, depth limit and errors; glPushAttrib(GL_TRANSFORM_BIT) keeps the
// matrix mode.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

class TextureMatrixTest : public GLTest {};

TEST_F(TextureMatrixTest, InitialStateIsIdentityAtDepthOne) {
  EXPECT_EQ(GetInt(GL_MAX_TEXTURE_STACK_DEPTH) >= 2, true);
  EXPECT_EQ(GetInt(GL_TEXTURE_STACK_DEPTH), 1);
  auto m = GetFloats<16>(GL_TEXTURE_MATRIX);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(m[i], i % 5 == 0 ? 1.0f : 0.0f) << i;
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, MatrixModeTextureAddressesTheActiveUnit) {
  glMatrixMode(GL_TEXTURE);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_TEXTURE);
  glScalef(2, 3, 4);
  glActiveTexture(GL_TEXTURE1);
  glTranslatef(5, 6, 7);
  EXPECT_NO_GL_ERROR();
  auto m1 = GetFloats<16>(GL_TEXTURE_MATRIX);
  EXPECT_EQ(m1[0], 1.0f);
  EXPECT_EQ(m1[12], 5.0f);
  EXPECT_EQ(m1[13], 6.0f);
  EXPECT_EQ(m1[14], 7.0f);
  glActiveTexture(GL_TEXTURE0);
  auto m0 = GetFloats<16>(GL_TEXTURE_MATRIX);
  EXPECT_EQ(m0[0], 2.0f);
  EXPECT_EQ(m0[5], 3.0f);
  EXPECT_EQ(m0[10], 4.0f);
  EXPECT_EQ(m0[12], 0.0f);
  // The modelview is untouched.
  auto mv = GetFloats<16>(GL_MODELVIEW_MATRIX);
  EXPECT_EQ(mv[0], 1.0f);
  EXPECT_EQ(mv[12], 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, TransposeQueries) {
  glMatrixMode(GL_TEXTURE);
  glTranslatef(5, 6, 7);
  auto t = GetFloats<16>(GL_TRANSPOSE_TEXTURE_MATRIX);
  EXPECT_EQ(t[3], 5.0f);
  EXPECT_EQ(t[7], 6.0f);
  EXPECT_EQ(t[11], 7.0f);
  EXPECT_EQ(t[12], 0.0f);
  glMatrixMode(GL_PROJECTION);
  glTranslatef(1, 2, 3);
  EXPECT_EQ(GetFloats<16>(GL_TRANSPOSE_PROJECTION_MATRIX)[3], 1.0f);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(4, 2, 3);
  EXPECT_EQ(GetFloats<16>(GL_TRANSPOSE_MODELVIEW_MATRIX)[3], 4.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, TransposeTextureMatrixOfTheActiveUnit) {
  GLFX_SKIP_ON_MESA("Mesa's GL_TRANSPOSE_TEXTURE_MATRIX is always unit 0's (get.c reads the first stack)");
  glMatrixMode(GL_TEXTURE);
  glActiveTexture(GL_TEXTURE1);
  glTranslatef(5, 6, 7);
  EXPECT_EQ(GetFloats<16>(GL_TRANSPOSE_TEXTURE_MATRIX)[3], 5.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, PushPopPerUnitAndTheDepthLimit) {
  glMatrixMode(GL_TEXTURE);
  const int max = GetInt(GL_MAX_TEXTURE_STACK_DEPTH);
  EXPECT_EQ(max, 10);  // as Mesa
  glPushMatrix();
  glScalef(2, 2, 2);
  EXPECT_EQ(GetInt(GL_TEXTURE_STACK_DEPTH), 2);
  glActiveTexture(GL_TEXTURE2);
  EXPECT_EQ(GetInt(GL_TEXTURE_STACK_DEPTH), 1);
  for (int i = 1; i < max; ++i) glPushMatrix();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_STACK_DEPTH), max);
  glPushMatrix();
  EXPECT_GL_ERROR(GL_STACK_OVERFLOW);
  for (int i = 1; i < max; ++i) glPopMatrix();
  glPopMatrix();
  EXPECT_GL_ERROR(GL_STACK_UNDERFLOW);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(GetFloats<16>(GL_TEXTURE_MATRIX)[0], 2.0f);
  glPopMatrix();
  EXPECT_EQ(GetFloats<16>(GL_TEXTURE_MATRIX)[0], 1.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, LoadAndMultTranspose) {
  glMatrixMode(GL_TEXTURE);
  const GLfloat rows[16] = {1, 0, 0, 9, 0, 1, 0, 8, 0, 0, 1, 7, 0, 0, 0, 1};
  glLoadTransposeMatrixf(rows);
  auto m = GetFloats<16>(GL_TEXTURE_MATRIX);
  EXPECT_EQ(m[12], 9.0f);
  EXPECT_EQ(m[13], 8.0f);
  EXPECT_EQ(m[14], 7.0f);
  glLoadIdentity();
  EXPECT_EQ(GetFloats<16>(GL_TEXTURE_MATRIX)[12], 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, TransformBitKeepsTheMatrixModeNotTheMatrix) {
  glMatrixMode(GL_TEXTURE);
  glPushAttrib(GL_TRANSFORM_BIT);
  glMatrixMode(GL_MODELVIEW);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_TEXTURE);
  glPushAttrib(GL_TRANSFORM_BIT);
  glScalef(3, 3, 3);
  glPopAttrib();
  EXPECT_EQ(GetFloats<16>(GL_TEXTURE_MATRIX)[0], 3.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureMatrixTest, BadModeAndInsideBeginEnd) {
  glMatrixMode(GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  glMatrixMode(GL_TEXTURE);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_MATRIX_MODE), GL_MODELVIEW);
}

}  // namespace
}  // namespace glfx_test
