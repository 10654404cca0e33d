// Texture objects (GL 2.1 §3.8.12): names, binding per target and unit, the
// target fixed at first bind, deletion unbinding, priorities, residency,
// sharing between contexts that share lists.
#include "api/gl_test_fixture.h"

using namespace glfx_test;

namespace {

class TextureObjectTest : public GLTest {};

TEST_F(TextureObjectTest, NamesBecomeTexturesWhenBound) {
  GLuint t[3] = {0, 0, 0};
  glGenTextures(3, t);
  EXPECT_NO_GL_ERROR();
  EXPECT_NE(t[0], 0u);
  EXPECT_NE(t[0], t[1]);
  EXPECT_NE(t[1], t[2]);
  EXPECT_EQ(glIsTexture(t[0]), GL_FALSE);  // a name only, until bound
  glBindTexture(GL_TEXTURE_2D, t[0]);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsTexture(t[0]), GL_TRUE);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), static_cast<GLint>(t[0]));
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_1D), 0);
  EXPECT_EQ(glIsTexture(0), GL_FALSE);
  glDeleteTextures(3, t);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsTexture(t[0]), GL_FALSE);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);  // deleting a bound texture binds 0
  glGenTextures(-1, t);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteTextures(-1, t);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(TextureObjectTest, NewNamesFollowTheHighestInUse) {
  glBindTexture(GL_TEXTURE_2D, 40);  // any unused name may be bound
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsTexture(40), GL_TRUE);
  GLuint t = 0;
  glGenTextures(1, &t);
  EXPECT_GT(t, 40u);  // Mesa: past the highest name
}

TEST_F(TextureObjectTest, TargetIsFixedAtFirstBind) {
  glBindTexture(GL_TEXTURE_2D, 5);
  ASSERT_NO_GL_ERROR();
  glBindTexture(GL_TEXTURE_1D, 5);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_1D), 0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 5);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBindTexture(GL_TEXTURE_2D, 5);
  EXPECT_NO_GL_ERROR();
  glBindTexture(GL_PROXY_TEXTURE_2D, 5);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBindTexture(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 6);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBindTexture(GL_TEXTURE_3D, 7);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 8);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_3D), 7);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_CUBE_MAP), 8);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 5);
}

TEST_F(TextureObjectTest, BindingsArePerUnitAndDeletionUnbindsEveryUnit) {
  glBindTexture(GL_TEXTURE_2D, 3);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);
  glBindTexture(GL_TEXTURE_2D, 3);
  glBindTexture(GL_TEXTURE_1D, 4);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 3);
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_1D), 0);
  GLuint names[2] = {3, 4};
  glDeleteTextures(2, names);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);
  glActiveTexture(GL_TEXTURE1);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_1D), 0);
  // A deleted name may be bound again, to another target: a new object.
  glBindTexture(GL_TEXTURE_3D, 3);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_3D), 3);
}

TEST_F(TextureObjectTest, PrioritiesAndResidency) {
  glBindTexture(GL_TEXTURE_2D, 5);
  glBindTexture(GL_TEXTURE_1D, 6);
  GLuint names[2] = {5, 6};
  GLfloat priorities[2] = {0.5f, 2.0f};
  glPrioritizeTextures(2, names, priorities);
  EXPECT_NO_GL_ERROR();
  GLfloat p = -1;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_FLOAT_EQ(p, 0.5f);
  glGetTexParameterfv(GL_TEXTURE_1D, GL_TEXTURE_PRIORITY, &p);
  EXPECT_FLOAT_EQ(p, 1.0f);  // clamped to [0, 1]
  glPrioritizeTextures(-1, names, priorities);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  GLuint withDefault[2] = {0, 5};
  glPrioritizeTextures(2, withDefault, priorities);
  EXPECT_NO_GL_ERROR();  // 0 is skipped

  GLboolean residences[2] = {7, 7};
  EXPECT_EQ(glAreTexturesResident(2, names, residences), GL_TRUE);
  EXPECT_EQ(residences[0], 7);  // all resident: left untouched
  EXPECT_NO_GL_ERROR();
  GLuint bad[2] = {5, 999};
  EXPECT_EQ(glAreTexturesResident(2, bad, residences), GL_FALSE);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(glAreTexturesResident(2, withDefault, residences), GL_FALSE);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
}

TEST_F(TextureObjectTest, BindingsInTextureBit) {
  glBindTexture(GL_TEXTURE_2D, 5);
  glPushAttrib(GL_TEXTURE_BIT);
  glBindTexture(GL_TEXTURE_2D, 6);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 6);
  glPopAttrib();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 5);
}

// GL_TEXTURE_BIT holds the parameters of the bound objects too (table 6.23).
TEST_F(TextureObjectTest, BoundObjectsParametersInTextureBit) {
  glBindTexture(GL_TEXTURE_2D, 5);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP);  // the default 1D texture
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glPopAttrib();
  EXPECT_NO_GL_ERROR();
  GLint v = 0;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_EQ(v, GL_LINEAR);
  glGetTexParameteriv(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, &v);
  EXPECT_EQ(v, GL_CLAMP);
}

TEST_F(TextureObjectTest, BindInDisplayList) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_2D, 9);
  glEndList();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);
  glCallList(list);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 9);
  glDeleteLists(list, 1);
}

TEST_F(TextureObjectTest, SharedWithContextsThatShareLists) {
  OSMesaContext shared = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, ctx_);
  OSMesaContext alone = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  ASSERT_NE(shared, nullptr);
  ASSERT_NE(alone, nullptr);
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  const GLubyte texel[4] = {10, 20, 30, 40};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  ASSERT_NO_GL_ERROR();

  std::vector<unsigned char> buffer(kWidth * kHeight * 4);
  ASSERT_EQ(OSMesaMakeCurrent(shared, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(glIsTexture(t), GL_TRUE);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);  // bindings are per context
  glBindTexture(GL_TEXTURE_2D, t);
  GLubyte back[4] = {0, 0, 0, 0};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[0], 10);
  EXPECT_EQ(back[3], 40);

  ASSERT_EQ(OSMesaMakeCurrent(alone, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  EXPECT_EQ(glIsTexture(t), GL_FALSE);
  EXPECT_NO_GL_ERROR();

  ASSERT_EQ(OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, kWidth, kHeight), GL_TRUE);
  OSMesaDestroyContext(shared);
  OSMesaDestroyContext(alone);
  EXPECT_EQ(glIsTexture(t), GL_TRUE);
}

}  // namespace
