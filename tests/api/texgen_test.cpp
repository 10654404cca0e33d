// Texture coordinate generation state (GL 2.1 §2.11.4, table 6.26):
// glTexGen/glGetTexGen per unit, the initial values, the modes each
// coordinate accepts, the eye plane stored times the inverse modelview, and
// the errors.
#include "gl_test_fixture.h"

namespace glfx_test {
namespace {

class TexGenTest : public GLTest {};

TEST_F(TexGenTest, InitialValues) {
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  for (int c = 0; c < 4; ++c) {
    GLint mode = 0;
    glGetTexGeniv(coords[c], GL_TEXTURE_GEN_MODE, &mode);
    EXPECT_EQ(mode, GL_EYE_LINEAR);
    GLfloat object[4], eye[4];
    glGetTexGenfv(coords[c], GL_OBJECT_PLANE, object);
    glGetTexGenfv(coords[c], GL_EYE_PLANE, eye);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(object[i], (c < 2 && i == c) ? 1.0f : 0.0f) << c << " " << i;
      EXPECT_EQ(eye[i], (c < 2 && i == c) ? 1.0f : 0.0f) << c << " " << i;
    }
  }
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_GEN_S), GL_FALSE);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexGenTest, ModesPerCoordinate) {
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  const GLenum modes[5] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_REFLECTION_MAP, GL_NORMAL_MAP};
  for (int c = 0; c < 4; ++c)
    for (GLenum mode : modes) {
      glTexGeni(coords[c], GL_TEXTURE_GEN_MODE, mode);
      const bool allowed =
          mode == GL_SPHERE_MAP ? c < 2 : (mode == GL_OBJECT_LINEAR || mode == GL_EYE_LINEAR) || c < 3;
      EXPECT_GL_ERROR(allowed ? GL_NO_ERROR : GL_INVALID_ENUM) << c << " " << mode;
      GLint got = 0;
      glGetTexGeniv(coords[c], GL_TEXTURE_GEN_MODE, &got);
      if (allowed) EXPECT_EQ(got, static_cast<GLint>(mode));
    }
  GLfloat f = 0;
  glTexGenf(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glGetTexGenfv(GL_S, GL_TEXTURE_GEN_MODE, &f);
  EXPECT_EQ(f, static_cast<GLfloat>(GL_OBJECT_LINEAR));
  GLdouble d = 0;
  const GLdouble sphere = GL_SPHERE_MAP;
  glTexGendv(GL_T, GL_TEXTURE_GEN_MODE, &sphere);
  glGetTexGendv(GL_T, GL_TEXTURE_GEN_MODE, &d);
  EXPECT_EQ(d, static_cast<GLdouble>(GL_SPHERE_MAP));
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexGenTest, Errors) {
  glTexGeni(GL_TEXTURE_2D, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexGeni(GL_S, GL_TEXTURE_2D, GL_OBJECT_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_TEXTURE_2D);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLint v[4];
  glGetTexGeniv(GL_TEXTURE_2D, GL_TEXTURE_GEN_MODE, v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexGeniv(GL_S, GL_TEXTURE_2D, v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBegin(GL_POINTS);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
}

// Mesa takes a plane from the scalar calls as (param, 0, 0, 0), without an
// error, as it does for glLightf(GL_POSITION) and glFogf(GL_FOG_COLOR).
TEST_F(TexGenTest, ScalarPlaneIsTheValueThenZeros) {
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTexGenf(GL_S, GL_OBJECT_PLANE, 2.0f);
  EXPECT_GL_ERROR(GL_NO_ERROR);
  glTexGeni(GL_T, GL_EYE_PLANE, 3);
  glTexGend(GL_R, GL_OBJECT_PLANE, 0.25);
  EXPECT_GL_ERROR(GL_NO_ERROR);
  GLfloat s[4], t[4], r[4];
  glGetTexGenfv(GL_S, GL_OBJECT_PLANE, s);
  glGetTexGenfv(GL_T, GL_EYE_PLANE, t);
  glGetTexGenfv(GL_R, GL_OBJECT_PLANE, r);
  const GLfloat wantS[4] = {2, 0, 0, 0}, wantT[4] = {3, 0, 0, 0}, wantR[4] = {0.25f, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(s[i], wantS[i]) << i;
    EXPECT_EQ(t[i], wantT[i]) << i;
    EXPECT_EQ(r[i], wantR[i]) << i;
  }
}

TEST_F(TexGenTest, PlanesPerUnitAndEyePlaneThroughTheInverseModelview) {
  const GLfloat plane[4] = {1, 2, 3, 4};
  glActiveTexture(GL_TEXTURE1);
  glTexGenfv(GL_R, GL_OBJECT_PLANE, plane);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1, 0, 0);  // M = T(1, 0, 0) S(2): M^-1 = S(1/2) T(-1, 0, 0)
  glScalef(2, 2, 2);
  glTexGenfv(GL_R, GL_EYE_PLANE, plane);
  GLfloat object[4], eye[4];
  glGetTexGenfv(GL_R, GL_OBJECT_PLANE, object);
  glGetTexGenfv(GL_R, GL_EYE_PLANE, eye);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(object[i], plane[i]);
  // The row vector (1, 2, 3, 4) times M^-1: (0.5, 1, 1.5, 4 - 0.5).
  EXPECT_EQ(eye[0], 0.5f);
  EXPECT_EQ(eye[1], 1.0f);
  EXPECT_EQ(eye[2], 1.5f);
  EXPECT_EQ(eye[3], 3.5f);
  GLint ie[4];
  const GLint half[4] = {1, 0, 0, 0};
  glLoadIdentity();
  glTexGeniv(GL_Q, GL_OBJECT_PLANE, half);
  glGetTexGeniv(GL_Q, GL_OBJECT_PLANE, ie);
  EXPECT_EQ(ie[0], 1);
  glActiveTexture(GL_TEXTURE0);
  glGetTexGenfv(GL_R, GL_OBJECT_PLANE, object);
  EXPECT_EQ(object[0], 0.0f);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TexGenTest, TextureBitSavesTexgen) {
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glPopAttrib();
  GLint mode = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_OBJECT_LINEAR);
  EXPECT_NO_GL_ERROR();
}

}  // namespace
}  // namespace glfx_test
