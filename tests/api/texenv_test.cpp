// glTexEnv* and glGetTexEnv* (GL 2.1 §3.8.13, §3.8.8, §3.4): the state of
// each unit's environment, its conversions, every error, display lists and
// glPushAttrib. Every value here holds on Mesa 22.3.6 too (the test also
// runs against Mesa).
#define GL_GLEXT_PROTOTYPES 1

#include <cmath>
#include <limits>

#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

class TexEnvTest : public GLTest {};

GLint EnvInt(GLenum pname, GLenum target = GL_TEXTURE_ENV) {
  GLint v = -12345;
  glGetTexEnviv(target, pname, &v);
  return v;
}
GLfloat EnvFloat(GLenum pname, GLenum target = GL_TEXTURE_ENV) {
  GLfloat v = -12345.0f;
  glGetTexEnvfv(target, pname, &v);
  return v;
}
std::array<GLfloat, 4> EnvColor() {
  std::array<GLfloat, 4> c{-1, -1, -1, -1};
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c.data());
  return c;
}

TEST_F(TexEnvTest, InitialStateOfEveryUnit) {
  EXPECT_EQ(GetInt(GL_MAX_TEXTURE_UNITS), 8);
  EXPECT_EQ(GetFloat(GL_MAX_TEXTURE_LOD_BIAS), 16.0f);
  for (int unit = 0; unit < 8; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_MODULATE);
    EXPECT_EQ(EnvColor(), (std::array<GLfloat, 4>{0, 0, 0, 0}));
    EXPECT_EQ(EnvInt(GL_COMBINE_RGB), GL_MODULATE);
    EXPECT_EQ(EnvInt(GL_COMBINE_ALPHA), GL_MODULATE);
    const GLint sources[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
    const GLint operandsRGB[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
    for (int n = 0; n < 3; ++n) {
      EXPECT_EQ(EnvInt(GL_SOURCE0_RGB + n), sources[n]);
      EXPECT_EQ(EnvInt(GL_SOURCE0_ALPHA + n), sources[n]);
      EXPECT_EQ(EnvInt(GL_OPERAND0_RGB + n), operandsRGB[n]);
      EXPECT_EQ(EnvInt(GL_OPERAND0_ALPHA + n), GL_SRC_ALPHA);
    }
    EXPECT_EQ(EnvFloat(GL_RGB_SCALE), 1.0f);
    EXPECT_EQ(EnvInt(GL_ALPHA_SCALE), 1);
    EXPECT_EQ(EnvFloat(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), 0.0f);
    EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_FALSE);
  }
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

TEST_F(TexEnvTest, EachUnitKeepsItsOwnState) {
  glActiveTexture(GL_TEXTURE2);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE7);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4.0f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -2.75f);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_MODULATE);
  EXPECT_EQ(EnvInt(GL_COMBINE_RGB), GL_MODULATE);
  EXPECT_EQ(EnvInt(GL_SOURCE1_ALPHA), GL_PREVIOUS);
  EXPECT_EQ(EnvInt(GL_ALPHA_SCALE), 1);
  EXPECT_EQ(EnvFloat(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), 0.0f);
  EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_FALSE);
  glActiveTexture(GL_TEXTURE2);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_COMBINE);
  EXPECT_EQ(EnvInt(GL_COMBINE_RGB), GL_DOT3_RGBA);
  EXPECT_EQ(EnvInt(GL_SOURCE1_ALPHA), GL_TEXTURE7);
  EXPECT_EQ(EnvFloat(GL_ALPHA_SCALE), 4.0f);
  EXPECT_EQ(EnvFloat(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), -2.75f);
  EXPECT_EQ(EnvInt(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), -2);  // truncated
  EXPECT_EQ(EnvFloat(GL_COORD_REPLACE, GL_POINT_SPRITE), 1.0f);
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

TEST_F(TexEnvTest, EveryModeFunctionSourceAndOperandIsStored) {
  for (GLenum mode : {GL_REPLACE, GL_MODULATE, GL_DECAL, GL_BLEND, GL_ADD, GL_COMBINE}) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(mode));
    EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), static_cast<GLint>(mode));
  }
  for (GLenum f : {GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB,
                   GL_DOT3_RGBA}) {
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, static_cast<GLint>(f));
    EXPECT_EQ(EnvInt(GL_COMBINE_RGB), static_cast<GLint>(f));
  }
  for (GLenum f : {GL_REPLACE, GL_MODULATE, GL_ADD, GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT}) {
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, static_cast<GLint>(f));
    EXPECT_EQ(EnvInt(GL_COMBINE_ALPHA), static_cast<GLint>(f));
  }
  for (int n = 0; n < 3; ++n) {
    for (GLenum s :
         {GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS, GL_TEXTURE0, GL_TEXTURE3, GL_TEXTURE7}) {
      glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + n, static_cast<GLint>(s));
      glTexEnvf(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + n, static_cast<GLfloat>(s));
      EXPECT_EQ(EnvInt(GL_SOURCE0_RGB + n), static_cast<GLint>(s));
      EXPECT_EQ(EnvFloat(GL_SOURCE0_ALPHA + n), static_cast<GLfloat>(s));
    }
    for (GLenum o : {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}) {
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + n, static_cast<GLint>(o));
      EXPECT_EQ(EnvInt(GL_OPERAND0_RGB + n), static_cast<GLint>(o));
    }
    for (GLenum o : {GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA}) {
      glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + n, static_cast<GLint>(o));
      EXPECT_EQ(EnvInt(GL_OPERAND0_ALPHA + n), static_cast<GLint>(o));
    }
  }
  for (GLint scale : {2, 4, 1}) {
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, scale);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, static_cast<GLfloat>(scale));
    EXPECT_EQ(EnvInt(GL_RGB_SCALE), scale);
    EXPECT_EQ(EnvFloat(GL_ALPHA_SCALE), static_cast<GLfloat>(scale));
  }
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

TEST_F(TexEnvTest, ReplaceExtIsStoredAsReplaceAndFloatEnumsAreTruncated) {
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, 0x8062);  // GL_REPLACE_EXT
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_REPLACE);
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLfloat>(GL_ADD) + 0.75f);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_ADD);
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

TEST_F(TexEnvTest, ColourIsClampedAndConverted) {
  const GLfloat c[4] = {-1.0f, 0.5f, 2.0f, 0.25f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
  EXPECT_EQ(EnvColor(), (std::array<GLfloat, 4>{0.0f, 0.5f, 1.0f, 0.25f}));
  GLint i[4] = {0, 0, 0, 0};
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, i);
  EXPECT_EQ(i[0], 0);
  EXPECT_EQ(i[1], 1073741823);  // Mesa's FLOAT_TO_INT: (GLint)(2147483647.0 * 0.5)
  EXPECT_EQ(i[2], 2147483647);
  EXPECT_EQ(i[3], 536870911);
  const GLint ic[4] = {std::numeric_limits<GLint>::max(), 0, -1, std::numeric_limits<GLint>::min()};
  glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ic);
  const std::array<GLfloat, 4> got = EnvColor();
  EXPECT_EQ(got[0], 1.0f);
  EXPECT_EQ(got[1], 1.0f / 4294967294.0f);  // (2c + 1) / (2^32 - 2): zero maps above 0
  EXPECT_EQ(got[2], 0.0f);                  // -1 maps to -1 / (2^32 - 2), clamped
  EXPECT_EQ(got[3], 0.0f);
  // glTexEnvf of the colour reads one value: (v, 0, 0, 0).
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0.5f);
  EXPECT_EQ(EnvColor(), (std::array<GLfloat, 4>{0.5f, 0.0f, 0.0f, 0.0f}));
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

TEST_F(TexEnvTest, LodBiasIsStoredUnclamped) {
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 100.5f);
  EXPECT_EQ(EnvFloat(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), 100.5f);
  glTexEnvi(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -3);
  EXPECT_EQ(EnvInt(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), -3);
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

TEST_F(TexEnvTest, ErrorsLeaveTheStateAlone) {
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_REPLACE);  // bad target
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1);  // a pname of another target
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_INTERPOLATE);  // not a mode
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_ADD);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB);  // DOT3 is for RGB only
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DECAL);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(EnvInt(GL_COMBINE_ALPHA), GL_MODULATE);
  EXPECT_EQ(EnvInt(GL_COMBINE_RGB), GL_MODULATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE8);  // past GL_MAX_TEXTURE_UNITS
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_SRC_COLOR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(EnvInt(GL_SOURCE0_RGB), GL_TEXTURE);
  EXPECT_EQ(EnvInt(GL_SOURCE2_ALPHA), GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, GL_SRC_COLOR);  // colour operands are for RGB only
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_PREVIOUS);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(EnvInt(GL_OPERAND1_ALPHA), GL_SRC_ALPHA);
  EXPECT_EQ(EnvInt(GL_OPERAND1_RGB), GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 3);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.5f);  // a float scale is not truncated
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(EnvInt(GL_RGB_SCALE), 1);
  EXPECT_EQ(EnvInt(GL_ALPHA_SCALE), 1);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexEnvi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_TRUE);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexEnvi(GL_TEXTURE_FILTER_CONTROL, GL_COORD_REPLACE, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_FALSE);
  EXPECT_EQ(EnvFloat(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), 0.0f);
}

TEST_F(TexEnvTest, QueryErrors) {
  GLint v = -7;
  glGetTexEnviv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLfloat f = -7.0f;
  glGetTexEnvfv(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, &f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, &f);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(v, -7);
  EXPECT_EQ(f, -7.0f);
}

TEST_F(TexEnvTest, InsideBeginEndIsAnError) {
  glBegin(GL_POINTS);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_MODULATE);
  glBegin(GL_POINTS);
  GLint v = -7;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(v, -7);
}

TEST_F(TexEnvTest, DisplayListsRecordTheCommands) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  const GLint ic[4] = {0, std::numeric_limits<GLint>::max(), 0, std::numeric_limits<GLint>::max()};
  glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ic);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f);  // the error comes when the list runs
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glEndList();
  EXPECT_GL_ERROR(GL_NO_ERROR);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_MODULATE);
  EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_FALSE);
  glActiveTexture(GL_TEXTURE3);  // the list addresses the unit active when it runs
  glCallList(list);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_COMBINE);
  EXPECT_EQ(EnvColor()[1], 1.0f);
  EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_TRUE);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_MODULATE);
  glDeleteLists(list, 1);
}

TEST_F(TexEnvTest, PushAttribRestoresTheEnvironment) {
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_ONE_MINUS_SRC_COLOR);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_COLOR);
  const GLfloat c[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f);
  glActiveTexture(GL_TEXTURE4);
  glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 4);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_ACTIVE_TEXTURE), GL_TEXTURE1);
  EXPECT_EQ(EnvInt(GL_TEXTURE_ENV_MODE), GL_BLEND);
  EXPECT_EQ(EnvInt(GL_OPERAND2_RGB), GL_ONE_MINUS_SRC_COLOR);
  EXPECT_EQ(EnvColor(), (std::array<GLfloat, 4>{0, 0, 0, 0}));
  EXPECT_EQ(EnvFloat(GL_TEXTURE_LOD_BIAS, GL_TEXTURE_FILTER_CONTROL), 0.0f);
  glActiveTexture(GL_TEXTURE4);
  EXPECT_EQ(EnvInt(GL_RGB_SCALE), 1);
  // GL_COORD_REPLACE is point state (GL_POINT_BIT).
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glPopAttrib();
  EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_FALSE);
  glPushAttrib(GL_POINT_BIT);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  glPopAttrib();
  EXPECT_EQ(EnvInt(GL_COORD_REPLACE, GL_POINT_SPRITE), GL_FALSE);
  EXPECT_GL_ERROR(GL_NO_ERROR);
}

}  // namespace
}  // namespace glfx_test
