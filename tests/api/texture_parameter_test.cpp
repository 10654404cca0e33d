// Texture parameters (GL 2.1 §3.8.4, table 6.23), mipmap generation with
// llvmpipe's filter, glCopyTexImage, and texture commands in display lists.
#include "api/gl_test_fixture.h"

using namespace glfx_test;

#ifndef GL_COMPARE_R_TO_TEXTURE
#define GL_COMPARE_R_TO_TEXTURE 0x884E
#endif

extern "C" void glGenerateMipmap(GLenum target);

namespace {

class TextureParameterTest : public GLTest {};

GLint Param(GLenum target, GLenum pname) {
  GLint v = -12345;
  glGetTexParameteriv(target, pname, &v);
  return v;
}
GLfloat ParamF(GLenum target, GLenum pname) {
  GLfloat v = -12345;
  glGetTexParameterfv(target, pname, &v);
  return v;
}

TEST_F(TextureParameterTest, InitialValues) {
  for (GLenum target : {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP}) {
    EXPECT_EQ(Param(target, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
    EXPECT_EQ(Param(target, GL_TEXTURE_MAG_FILTER), GL_LINEAR);
    EXPECT_EQ(Param(target, GL_TEXTURE_WRAP_S), GL_REPEAT);
    EXPECT_EQ(Param(target, GL_TEXTURE_WRAP_T), GL_REPEAT);
    EXPECT_EQ(Param(target, GL_TEXTURE_WRAP_R), GL_REPEAT);
    EXPECT_EQ(ParamF(target, GL_TEXTURE_MIN_LOD), -1000.0f);
    EXPECT_EQ(ParamF(target, GL_TEXTURE_MAX_LOD), 1000.0f);
    EXPECT_EQ(Param(target, GL_TEXTURE_BASE_LEVEL), 0);
    EXPECT_EQ(Param(target, GL_TEXTURE_MAX_LEVEL), 1000);
    EXPECT_EQ(ParamF(target, GL_TEXTURE_PRIORITY), 1.0f);
    EXPECT_EQ(Param(target, GL_TEXTURE_RESIDENT), GL_TRUE);
    EXPECT_EQ(Param(target, GL_GENERATE_MIPMAP), GL_FALSE);
    EXPECT_EQ(Param(target, GL_TEXTURE_COMPARE_MODE), GL_NONE);
    EXPECT_EQ(Param(target, GL_TEXTURE_COMPARE_FUNC), GL_LEQUAL);
    EXPECT_EQ(Param(target, GL_DEPTH_TEXTURE_MODE), GL_LUMINANCE);
    GLfloat border[4] = {-1, -1, -1, -1};
    glGetTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, border);
    for (GLfloat c : border) EXPECT_EQ(c, 0.0f);
  }
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureParameterTest, SetAndQueryEveryParameter) {
  glBindTexture(GL_TEXTURE_2D, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_BORDER);
  const GLfloat border[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -2.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 7.25f);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 5);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0.25f);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER), GL_LINEAR_MIPMAP_NEAREST);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER), GL_NEAREST);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T), GL_MIRRORED_REPEAT);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R), GL_CLAMP_TO_BORDER);
  GLfloat b[4];
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, b);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(b[i], border[i]);
  GLint bi[4];
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, bi);
  EXPECT_NEAR(bi[0], NormalizedToInt(0.25), 1.0);
  EXPECT_EQ(bi[3], 2147483647);
  EXPECT_EQ(ParamF(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD), -2.5f);
  EXPECT_EQ(ParamF(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD), 7.25f);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD), 7);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL), 2);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL), 5);
  EXPECT_EQ(ParamF(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY), 0.25f);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_GENERATE_MIPMAP), GL_TRUE);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE), GL_COMPARE_R_TO_TEXTURE);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC), GL_GREATER);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE), GL_INTENSITY);
  // Per object: the default texture and another target are untouched.
  glBindTexture(GL_TEXTURE_2D, 0);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 3);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL), 5);
  EXPECT_EQ(Param(GL_TEXTURE_1D, GL_TEXTURE_MAX_LEVEL), 1000);
}

TEST_F(TextureParameterTest, Errors) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_CLAMP);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LESS);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_REPEAT);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGBA);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, 1);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  GLint v;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WIDTH, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glGetTexParameteriv(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL), 1000);
}

// llvmpipe makes the levels with a linear blit: a 2x2 box is averaged a row
// at a time, rounding half up each time; odd sizes sample at each texel's
// centre.
TEST_F(TextureParameterTest, MipmapsAsLlvmpipeMakesThem) {
  enum { W = 64 };
  std::vector<GLubyte> px(W * 2 * 4);
  uint32_t seed = 12345;
  for (GLubyte& b : px) {
    seed = seed * 1103515245u + 12345u;
    b = static_cast<GLubyte>(seed >> 16);
  }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  ASSERT_NO_GL_ERROR();
  std::vector<GLubyte> level1(W / 2 * 4);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, level1.data());
  for (int i = 0; i < W / 2; ++i)
    for (int c = 0; c < 4; ++c) {
      const int a = px[(2 * i) * 4 + c], b = px[(2 * i + 1) * 4 + c];
      const int d = px[(W + 2 * i) * 4 + c], e = px[(W + 2 * i + 1) * 4 + c];
      const int expected = (((a + b + 1) >> 1) + ((d + e + 1) >> 1) + 1) >> 1;
      EXPECT_EQ(level1[i * 4 + c], expected) << i << " " << c;
    }
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);
  GLint w = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 6, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 1);

  const GLubyte five[5 * 4] = {0,   0,   0,  0,  100, 100, 100, 100, 200, 200,
                               200, 200, 40, 40, 40,  40,  255, 255, 255, 255};
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 5, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, five);
  GLubyte out[8];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 75);
  EXPECT_EQ(out[4], 94);
  glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 85);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);  // not cube complete
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP_POSITIVE_X);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

TEST_F(TextureParameterTest, CopyTexImage) {
  glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 60, 60, 8, 8, 0);
  ASSERT_NO_GL_ERROR();
  std::vector<GLubyte> out(8 * 8 * 4);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(out[0], 51);
  EXPECT_EQ(out[1], 102);
  EXPECT_EQ(out[2], 153);
  EXPECT_EQ(out[3], 204);
  EXPECT_EQ(out[(7 * 8 + 7) * 4], 0);  // outside the framebuffer
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 0, 0, 4, 0);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(out[0], 51);
  EXPECT_EQ(out[1], 0);
  EXPECT_EQ(out[3], 255);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, 4, 4, 0);
  GLushort d = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, out.data());
  std::memcpy(&d, out.data(), 2);
  EXPECT_EQ(d, 0xffff);
  EXPECT_NO_GL_ERROR();
  for (GLint bad : {0, 1, 3, 4}) {
    glCopyTexImage2D(GL_TEXTURE_2D, 0, bad, 0, 0, 4, 4, 0);
    EXPECT_GL_ERROR(GL_INVALID_ENUM) << bad;
  }
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 4, 2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, -1, 4, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA8, 0, 0, 4, 4, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glCopyTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 4, 0);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);

  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 0, 0, 4, 4, 0);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 0, 0, 2, 2);
  EXPECT_NO_GL_ERROR();
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 0, 0, 2, 2);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 0, 0, 1, 1);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 0, 0, 4);
  EXPECT_NO_GL_ERROR();
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 1, 1);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  std::vector<GLubyte> zero(2 * 2 * 2 * 4, 0);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, zero.data());
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 0, 0, 2, 2);
  EXPECT_NO_GL_ERROR();
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(out[16], 51);

  glPixelTransferf(GL_RED_SCALE, 2.0f);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 4, 4, 0);
  glPixelTransferf(GL_RED_SCALE, 1.0f);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(out[0], 102);
  EXPECT_NO_GL_ERROR();
}

TEST_F(TextureParameterTest, GenericCompressedFormatsHaveNoCompressedData) {
  GLubyte data[16] = {};
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 4, 4, 0, 16, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 16, data);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
}

// §5.4: a texture image in a list is the one in client memory at compile
// time, unpacked with the pixel store state of then.
TEST_F(TextureParameterTest, DisplayListsCaptureImages) {
  GLubyte px[2 * 4] = {1, 2, 3, 4, 5, 6, 7, 8};
  GLuint list = glGenLists(1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glNewList(list, GL_COMPILE);
  glBindTexture(GL_TEXTURE_2D, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // runs now
  glEndList();
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  px[4] = 99;
  GLint w = -1;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 8);
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 0);
  glCallList(list);
  ASSERT_NO_GL_ERROR();
  EXPECT_EQ(GetInt(GL_TEXTURE_BINDING_2D), 4);
  EXPECT_EQ(Param(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER), GL_NEAREST);
  GLubyte back[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  EXPECT_EQ(back[0], 5);
  EXPECT_EQ(back[3], 8);
  glDeleteLists(list, 1);
}

}  // namespace
