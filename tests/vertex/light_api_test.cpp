// The lighting entry points (api/gl_light_api.cpp) and the lighting part of
// glEnable/glGet (vertex/lighting_queries.cpp): every default of GL 2.1 tables
// 6.11-6.13, every error (each leaving the state unchanged), and the value
// conversions, which follow Mesa 22.3 as measured:
//   - glLightiv/glMaterialiv/glLightModeliv colours: (2c + 1) / (2^32 - 2);
//   - glGetLightiv truncates toward zero, colours as (GLint)(2147483647.0 * c);
//   - glGetMaterialiv truncates colours the same way but rounds shininess and
//     colour indexes to nearest;
//   - glLightf/glLighti/glLightModelf with a vector pname set (param, 0, 0, 0).
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "state/capabilities.h"
#include "state/context.h"
#include "vertex/light_constants.h"
#include "vertex/lighting_queries.h"

namespace {

using namespace glfixed;
using glm::vec3;
using glm::vec4;

bool sameLight(const Light& a, const Light& b) {
  return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
         a.eyePosition == b.eyePosition && a.eyeSpotDirection == b.eyeSpotDirection &&
         a.spotExponent == b.spotExponent && a.spotCutoff == b.spotCutoff &&
         a.constantAttenuation == b.constantAttenuation && a.linearAttenuation == b.linearAttenuation &&
         a.quadraticAttenuation == b.quadraticAttenuation && a.enabled == b.enabled;
}
bool sameMaterial(const Material& a, const Material& b) {
  return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
         a.emission == b.emission && a.shininess == b.shininess && a.colorIndexes == b.colorIndexes;
}
bool sameLighting(const LightingAttrib& a, const LightingAttrib& b) {
  for (int i = 0; i < kMaxLights; ++i)
    if (!sameLight(a.light[i], b.light[i])) return false;
  return a.shadeModel == b.shadeModel && a.lighting == b.lighting && a.colorMaterial == b.colorMaterial &&
         a.colorMaterialFace == b.colorMaterialFace && a.colorMaterialParameter == b.colorMaterialParameter &&
         a.model.ambient == b.model.ambient && a.model.localViewer == b.model.localViewer &&
         a.model.twoSide == b.model.twoSide && a.model.colorControl == b.model.colorControl &&
         sameMaterial(a.material[0], b.material[0]) && sameMaterial(a.material[1], b.material[1]);
}

class LightApiTest : public ::testing::Test {
 protected:
  void SetUp() override { setCurrentContext(&ctx_); }
  void TearDown() override { setCurrentContext(nullptr); }

  // Runs `call`, expects `error` from it, and the lighting state unchanged.
  template <typename F>
  void expectRejected(GLenum error, F call, const char* what) {
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << what;
    const LightingAttrib before = ctx_.lighting;
    const TransformAttrib transformBefore = ctx_.transform;
    call();
    EXPECT_EQ(glGetError(), error) << what;
    EXPECT_TRUE(sameLighting(before, ctx_.lighting)) << what << " changed the lighting state";
    EXPECT_EQ(transformBefore.normalize, ctx_.transform.normalize) << what;
  }

  std::vector<float> lightf(GLenum light, GLenum pname, int n) {
    std::vector<float> v(4, -99.0f);
    glGetLightfv(light, pname, v.data());
    v.resize(n);
    return v;
  }
  std::vector<float> materialf(GLenum face, GLenum pname, int n) {
    std::vector<float> v(4, -99.0f);
    glGetMaterialfv(face, pname, v.data());
    v.resize(n);
    return v;
  }
  std::vector<GLint> lighti(GLenum light, GLenum pname, int n) {
    std::vector<GLint> v(4, -99);
    glGetLightiv(light, pname, v.data());
    v.resize(n);
    return v;
  }
  std::vector<GLint> materiali(GLenum face, GLenum pname, int n) {
    std::vector<GLint> v(4, -99);
    glGetMaterialiv(face, pname, v.data());
    v.resize(n);
    return v;
  }

  Context ctx_{24};
};

using V = std::vector<float>;
using VI = std::vector<GLint>;

// ---- defaults (GL 2.1 tables 6.11-6.13) -------------------------------------

TEST_F(LightApiTest, LightDefaults) {
  for (int i = 0; i < kMaxLights; ++i) {
    const GLenum l = GL_LIGHT0 + i;
    const float c = i == 0 ? 1.0f : 0.0f;
    EXPECT_EQ(lightf(l, GL_AMBIENT, 4), (V{0, 0, 0, 1})) << i;
    EXPECT_EQ(lightf(l, GL_DIFFUSE, 4), (V{c, c, c, 1})) << i;
    EXPECT_EQ(lightf(l, GL_SPECULAR, 4), (V{c, c, c, 1})) << i;
    EXPECT_EQ(lightf(l, GL_POSITION, 4), (V{0, 0, 1, 0})) << i;
    EXPECT_EQ(lightf(l, GL_SPOT_DIRECTION, 3), (V{0, 0, -1})) << i;
    EXPECT_EQ(lightf(l, GL_SPOT_EXPONENT, 1), (V{0})) << i;
    EXPECT_EQ(lightf(l, GL_SPOT_CUTOFF, 1), (V{180})) << i;
    EXPECT_EQ(lightf(l, GL_CONSTANT_ATTENUATION, 1), (V{1})) << i;
    EXPECT_EQ(lightf(l, GL_LINEAR_ATTENUATION, 1), (V{0})) << i;
    EXPECT_EQ(lightf(l, GL_QUADRATIC_ATTENUATION, 1), (V{0})) << i;
    const GLint ci = i == 0 ? 2147483647 : 0;
    EXPECT_EQ(lighti(l, GL_AMBIENT, 4), (VI{0, 0, 0, 2147483647})) << i;
    EXPECT_EQ(lighti(l, GL_DIFFUSE, 4), (VI{ci, ci, ci, 2147483647})) << i;
    EXPECT_EQ(lighti(l, GL_SPECULAR, 4), (VI{ci, ci, ci, 2147483647})) << i;
    EXPECT_EQ(lighti(l, GL_POSITION, 4), (VI{0, 0, 1, 0})) << i;
    EXPECT_EQ(lighti(l, GL_SPOT_DIRECTION, 3), (VI{0, 0, -1})) << i;
    EXPECT_EQ(lighti(l, GL_SPOT_EXPONENT, 1), (VI{0})) << i;
    EXPECT_EQ(lighti(l, GL_SPOT_CUTOFF, 1), (VI{180})) << i;
    EXPECT_EQ(lighti(l, GL_CONSTANT_ATTENUATION, 1), (VI{1})) << i;
    EXPECT_EQ(lighti(l, GL_LINEAR_ATTENUATION, 1), (VI{0})) << i;
    EXPECT_EQ(lighti(l, GL_QUADRATIC_ATTENUATION, 1), (VI{0})) << i;
    EXPECT_EQ(glIsEnabled(l), GL_FALSE) << i;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, MaterialDefaults) {
  for (GLenum face : {GL_FRONT, GL_BACK}) {
    EXPECT_EQ(materialf(face, GL_AMBIENT, 4), (V{0.2f, 0.2f, 0.2f, 1}));
    EXPECT_EQ(materialf(face, GL_DIFFUSE, 4), (V{0.8f, 0.8f, 0.8f, 1}));
    EXPECT_EQ(materialf(face, GL_SPECULAR, 4), (V{0, 0, 0, 1}));
    EXPECT_EQ(materialf(face, GL_EMISSION, 4), (V{0, 0, 0, 1}));
    EXPECT_EQ(materialf(face, GL_SHININESS, 1), (V{0}));
    EXPECT_EQ(materialf(face, GL_COLOR_INDEXES, 3), (V{0, 1, 1}));
    // (GLint)(2147483647.0 * 0.2f) and (GLint)(2147483647.0 * 0.8f), as Mesa.
    EXPECT_EQ(materiali(face, GL_AMBIENT, 4), (VI{429496735, 429496735, 429496735, 2147483647}));
    EXPECT_EQ(materiali(face, GL_DIFFUSE, 4), (VI{1717986943, 1717986943, 1717986943, 2147483647}));
    EXPECT_EQ(materiali(face, GL_SPECULAR, 4), (VI{0, 0, 0, 2147483647}));
    EXPECT_EQ(materiali(face, GL_EMISSION, 4), (VI{0, 0, 0, 2147483647}));
    EXPECT_EQ(materiali(face, GL_SHININESS, 1), (VI{0}));
    EXPECT_EQ(materiali(face, GL_COLOR_INDEXES, 3), (VI{0, 1, 1}));
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, LightModelAndOtherDefaults) {
  GLfloat f[4];
  glGetFloatv(GL_LIGHT_MODEL_AMBIENT, f);
  EXPECT_EQ((V{f[0], f[1], f[2], f[3]}), (V{0.2f, 0.2f, 0.2f, 1}));
  GLint i = -1;
  glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER, &i);
  EXPECT_EQ(i, GL_FALSE);
  glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, &i);
  EXPECT_EQ(i, GL_FALSE);
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &i);
  EXPECT_EQ(i, GL_SINGLE_COLOR);
  glGetIntegerv(GL_SHADE_MODEL, &i);
  EXPECT_EQ(i, GL_SMOOTH);
  glGetIntegerv(GL_COLOR_MATERIAL_FACE, &i);
  EXPECT_EQ(i, GL_FRONT_AND_BACK);
  glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &i);
  EXPECT_EQ(i, GL_AMBIENT_AND_DIFFUSE);
  glGetIntegerv(GL_MAX_LIGHTS, &i);
  EXPECT_EQ(i, 8);
  for (GLenum cap : {GL_LIGHTING, GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL})
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, QueriesOwnExactlyTheLightingPnames) {
  GLdouble v[16];
  int count = 0;
  for (GLenum p :
       {GL_LIGHTING, GL_LIGHT0, GL_LIGHT7, GL_COLOR_MATERIAL, GL_COLOR_MATERIAL_FACE,
        GL_COLOR_MATERIAL_PARAMETER, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE,
        GL_LIGHT_MODEL_COLOR_CONTROL, GL_SHADE_MODEL, GL_MAX_LIGHTS, GL_NORMALIZE, GL_RESCALE_NORMAL}) {
    EXPECT_TRUE(getLightingState(ctx_, p, v, &count)) << p;
    EXPECT_EQ(count, 1) << p;
  }
  EXPECT_TRUE(getLightingState(ctx_, GL_LIGHT_MODEL_AMBIENT, v, &count));
  EXPECT_EQ(count, 4);
  EXPECT_FALSE(getLightingState(ctx_, GL_DEPTH_TEST, v, &count));
  EXPECT_FALSE(getLightingState(ctx_, GL_LIGHT0 + 8, v, &count));
  // The capabilities are one table (state/capabilities.h): GL_LIGHT8 is none.
  EXPECT_EQ(findCapability(GL_LIGHT0 + 8), nullptr);
  ASSERT_NE(findCapability(GL_LIGHT7), nullptr);
  EXPECT_EQ(&findCapability(GL_LIGHT7)->flag(ctx_), &ctx_.lighting.light[7].enabled);
}

// ---- setting and converting ------------------------------------------------------

TEST_F(LightApiTest, EnableDisableEveryLightingCapability) {
  for (GLenum cap :
       {GL_LIGHTING, GL_LIGHT0, GL_LIGHT3, GL_LIGHT7, GL_COLOR_MATERIAL, GL_NORMALIZE, GL_RESCALE_NORMAL}) {
    glEnable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_TRUE) << cap;
    glDisable(cap);
    EXPECT_EQ(glIsEnabled(cap), GL_FALSE) << cap;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, IntegerColoursConvertAsMesa) {
  const GLint v[4] = {0, 2147483647, -2147483647 - 1, 1073741824};
  glLightiv(GL_LIGHT3, GL_AMBIENT, v);
  EXPECT_EQ(lightf(GL_LIGHT3, GL_AMBIENT, 4), (V{2.32830644e-10f, 1, -1, 0.5f}));
  EXPECT_EQ(lighti(GL_LIGHT3, GL_AMBIENT, 4), (VI{0, 2147483647, -2147483647, 1073741823}));
  glMaterialiv(GL_FRONT, GL_EMISSION, v);
  EXPECT_EQ(materialf(GL_FRONT, GL_EMISSION, 4), (V{2.32830644e-10f, 1, -1, 0.5f}));
  glLightModeliv(GL_LIGHT_MODEL_AMBIENT, v);
  EXPECT_EQ(ctx_.lighting.model.ambient, vec4(2.32830644e-10f, 1, -1, 0.5f));
  const GLint p[4] = {3, -4, 5, 0};
  glLightiv(GL_LIGHT3, GL_POSITION, p);
  EXPECT_EQ(lightf(GL_LIGHT3, GL_POSITION, 4), (V{3, -4, 5, 0}));
  glLighti(GL_LIGHT3, GL_SPOT_CUTOFF, 30);
  EXPECT_EQ(lightf(GL_LIGHT3, GL_SPOT_CUTOFF, 1), (V{30}));
  glMateriali(GL_BACK, GL_SHININESS, 17);
  EXPECT_EQ(materialf(GL_BACK, GL_SHININESS, 1), (V{17}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, IntegerQueriesTruncateAsMesa) {
  const GLfloat d[4] = {0.8f, -0.3f, 0.5f, 1.0f};
  glLightfv(GL_LIGHT2, GL_DIFFUSE, d);
  EXPECT_EQ(lighti(GL_LIGHT2, GL_DIFFUSE, 4), (VI{1717986943, -644245119, 1073741823, 2147483647}));
  const GLfloat p[4] = {1.7f, -1.7f, 2.5f, 1.0f};
  glLightfv(GL_LIGHT2, GL_POSITION, p);
  EXPECT_EQ(lighti(GL_LIGHT2, GL_POSITION, 4), (VI{1, -1, 2, 1}));
  glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 10.6f);
  EXPECT_EQ(lighti(GL_LIGHT2, GL_SPOT_EXPONENT, 1), (VI{10}));
  glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 45.5f);
  EXPECT_EQ(lighti(GL_LIGHT2, GL_SPOT_CUTOFF, 1), (VI{45}));
  const GLfloat sd[3] = {0.6f, -0.6f, -0.5f};
  glLightfv(GL_LIGHT2, GL_SPOT_DIRECTION, sd);
  EXPECT_EQ(lighti(GL_LIGHT2, GL_SPOT_DIRECTION, 3), (VI{0, 0, 0}));
  glMaterialf(GL_FRONT, GL_SHININESS, 10.5f);
  EXPECT_EQ(materiali(GL_FRONT, GL_SHININESS, 1), (VI{11}));
  glMaterialf(GL_FRONT, GL_SHININESS, 11.5f);
  EXPECT_EQ(materiali(GL_FRONT, GL_SHININESS, 1), (VI{12}));
  const GLfloat ci[3] = {1.6f, 2.5f, 3.5f};
  glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, ci);
  EXPECT_EQ(materiali(GL_FRONT, GL_COLOR_INDEXES, 3), (VI{2, 3, 4}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, ScalarCommandsWithVectorPnamesSetTheFirstComponent) {
  glLightf(GL_LIGHT1, GL_AMBIENT, 0.5f);
  EXPECT_EQ(lightf(GL_LIGHT1, GL_AMBIENT, 4), (V{0.5f, 0, 0, 0}));
  glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.5f);
  EXPECT_EQ(ctx_.lighting.model.ambient, vec4(0.5f, 0, 0, 0));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, PositionAndSpotDirectionAreStoredInEyeSpace) {
  // Translate (1, 2, 3) and scale 2, loaded as a matrix: exact in float.
  const GLfloat m[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1};
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(m);
  const GLfloat p1[4] = {1, 1, 1, 1}, p0[4] = {1, 1, 1, 0}, s[3] = {1, 0, 0};
  glLightfv(GL_LIGHT4, GL_POSITION, p1);
  EXPECT_EQ(lightf(GL_LIGHT4, GL_POSITION, 4), (V{3, 4, 5, 1}));
  glLightfv(GL_LIGHT4, GL_POSITION, p0);
  EXPECT_EQ(lightf(GL_LIGHT4, GL_POSITION, 4), (V{2, 2, 2, 0}));
  glLightfv(GL_LIGHT4, GL_SPOT_DIRECTION, s);  // the upper 3x3 only: no translation
  EXPECT_EQ(lightf(GL_LIGHT4, GL_SPOT_DIRECTION, 3), (V{2, 0, 0}));
  // A shear: the spot direction goes through the modelview itself, not its inverse transpose.
  const GLfloat shear[16] = {1, 0, 0, 0, 0.5f, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  glLoadMatrixf(shear);
  const GLfloat y[3] = {0, 1, 0};
  glLightfv(GL_LIGHT4, GL_SPOT_DIRECTION, y);
  EXPECT_EQ(lightf(GL_LIGHT4, GL_SPOT_DIRECTION, 3), (V{0.5f, 1, 0}));
  // Changing the modelview afterwards leaves stored positions alone.
  glLoadIdentity();
  EXPECT_EQ(lightf(GL_LIGHT4, GL_POSITION, 4), (V{2, 2, 2, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, LightModelValues) {
  glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 0.5f);
  EXPECT_TRUE(ctx_.lighting.model.twoSide);
  glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, -0.5f);
  EXPECT_TRUE(ctx_.lighting.model.localViewer);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  EXPECT_EQ(ctx_.lighting.model.colorControl, GLenum(GL_SEPARATE_SPECULAR_COLOR));
  glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 0);
  EXPECT_FALSE(ctx_.lighting.model.twoSide);
  glShadeModel(GL_FLAT);
  EXPECT_EQ(ctx_.lighting.shadeModel, GLenum(GL_FLAT));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, AcceptedBoundaryValues) {
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 0);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 128);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(ctx_.lighting.material[kBack].shininess, 128.0f);
}

// ---- errors: each leaves the state unchanged ----------------------------------

TEST_F(LightApiTest, LightErrors) {
  const GLfloat v[4] = {0.5f, 0.5f, 0.5f, 1};
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightfv(GL_LIGHT0 + 8, GL_AMBIENT, v); }, "GL_LIGHT8");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightf(GL_LIGHT0 - 1, GL_SPOT_CUTOFF, 30); }, "GL_LIGHT0 - 1");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLighti(GL_LIGHTING, GL_SPOT_CUTOFF, 30); }, "light GL_LIGHTING");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightf(GL_LIGHT0, GL_SHININESS, 1); }, "pname GL_SHININESS");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightfv(GL_LIGHT0, GL_EMISSION, v); }, "pname GL_EMISSION");
  expectRejected(
      GL_INVALID_ENUM,
      [&] {
        const GLint iv[4] = {1, 1, 1, 1};
        glLightiv(GL_LIGHT0, GL_AMBIENT_AND_DIFFUSE, iv);
      },
      "pname AMB_AND_DIFF");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90.5f); }, "cutoff 90.5");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, -0.5f); }, "cutoff -0.5");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 179.9f); }, "cutoff 179.9");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLighti(GL_LIGHT0, GL_SPOT_CUTOFF, 181); }, "cutoff 181");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 128.5f); }, "exponent 128.5");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, -0.5f); }, "exponent -0.5");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, -0.5f); }, "k0 < 0");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -1e-6f); }, "k1 < 0");
  expectRejected(
      GL_INVALID_VALUE, [&] { glLighti(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, -1); }, "k2 < 0");
}

TEST_F(LightApiTest, GetLightErrorsWriteNothing) {
  GLfloat f[4] = {-7, -7, -7, -7};
  GLint i[4] = {-7, -7, -7, -7};
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetLightfv(GL_LIGHT0 + 8, GL_AMBIENT, f); }, "get GL_LIGHT8");
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetLightiv(GL_LIGHT0, GL_SHININESS, i); }, "get pname GL_SHININESS");
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetLightfv(GL_LIGHT0, GL_LIGHT_MODEL_AMBIENT, f); }, "get pname model");
  EXPECT_EQ(f[0], -7.0f);
  EXPECT_EQ(i[0], -7);
}

TEST_F(LightApiTest, LightModelErrors) {
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightModelf(GL_LIGHT0, 0); }, "pname GL_LIGHT0");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightModeli(GL_SHADE_MODEL, 0); }, "pname GL_SHADE_MODEL");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, 5); }, "color control 5");
  expectRejected(
      GL_INVALID_ENUM, [&] { glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SMOOTH); },
      "color control SMOOTH");
}

TEST_F(LightApiTest, MaterialErrors) {
  const GLfloat v[4] = {0.5f, 0.5f, 0.5f, 1};
  expectRejected(
      GL_INVALID_ENUM, [&] { glMaterialfv(GL_LEFT, GL_AMBIENT, v); }, "face GL_LEFT");
  expectRejected(
      GL_INVALID_ENUM, [&] { glMaterialf(GL_FRONT_LEFT, GL_SHININESS, 1); }, "face GL_FRONT_LEFT");
  expectRejected(
      GL_INVALID_ENUM, [&] { glMaterialf(GL_LEFT, GL_POSITION, 1); }, "bad face and pname");
  expectRejected(
      GL_INVALID_ENUM, [&] { glMaterialfv(GL_FRONT, GL_POSITION, v); }, "pname GL_POSITION");
  expectRejected(
      GL_INVALID_ENUM, [&] { glMateriali(GL_BACK, GL_SPOT_CUTOFF, 1); }, "pname GL_SPOT_CUTOFF");
  expectRejected(
      GL_INVALID_VALUE, [&] { glMaterialf(GL_FRONT, GL_SHININESS, 128.5f); }, "shininess 128.5");
  expectRejected(
      GL_INVALID_VALUE, [&] { glMaterialf(GL_FRONT, GL_SHININESS, -1); }, "shininess -1");
  expectRejected(
      GL_INVALID_VALUE, [&] { glMateriali(GL_FRONT_AND_BACK, GL_SHININESS, 200); }, "shininess 200");
}

TEST_F(LightApiTest, GetMaterialErrorsWriteNothing) {
  GLfloat f[4] = {-7, -7, -7, -7};
  GLint i[4] = {-7, -7, -7, -7};
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, f); }, "get F&B");
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetMaterialiv(GL_LEFT, GL_AMBIENT, i); }, "get GL_LEFT");
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, f); }, "get AMB_AND_DIFF");
  expectRejected(
      GL_INVALID_ENUM, [&] { glGetMaterialiv(GL_BACK, GL_POSITION, i); }, "get GL_POSITION");
  EXPECT_EQ(f[0], -7.0f);
  EXPECT_EQ(i[0], -7);
}

TEST_F(LightApiTest, ColorMaterialAndShadeModelErrors) {
  expectRejected(
      GL_INVALID_ENUM, [&] { glColorMaterial(GL_FRONT, GL_SHININESS); }, "mode GL_SHININESS");
  expectRejected(
      GL_INVALID_ENUM, [&] { glColorMaterial(GL_FRONT, GL_COLOR_INDEXES); }, "mode GL_COLOR_INDEXES");
  expectRejected(
      GL_INVALID_ENUM, [&] { glColorMaterial(GL_LEFT, GL_DIFFUSE); }, "face GL_LEFT");
  expectRejected(
      GL_INVALID_ENUM, [&] { glShadeModel(GL_FLAT + 5); }, "shade model");
  expectRejected(
      GL_INVALID_ENUM, [&] { glShadeModel(GL_LINE); }, "shade model GL_LINE");
}

TEST_F(LightApiTest, BeginEndForbidsAllButMaterial) {
  const GLfloat v[4] = {0.5f, 0.5f, 0.5f, 1};
  GLfloat f[4];
  GLint i[4];
  auto inside = [&](auto call) {
    return [=] {
      glBegin(GL_POINTS);
      call();
      glEnd();
    };
  };
  expectRejected(GL_INVALID_OPERATION, inside([&] { glLightfv(GL_LIGHT0, GL_AMBIENT, v); }), "glLightfv");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glLighti(GL_LIGHT0, GL_SPOT_EXPONENT, 3); }), "glLighti");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glLightf(GL_LIGHT0 + 9, GL_SPOT_EXPONENT, 3); }),
                 "glLightf, bad light too");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v); }),
                 "glLightModelfv");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1); }),
                 "glLightModeli");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glColorMaterial(GL_FRONT, GL_EMISSION); }),
                 "glColorMaterial");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glShadeModel(GL_FLAT); }), "glShadeModel");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glGetLightfv(GL_LIGHT0, GL_AMBIENT, f); }),
                 "glGetLightfv");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glGetLightiv(GL_LIGHT0, GL_AMBIENT, i); }),
                 "glGetLightiv");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glGetMaterialfv(GL_FRONT, GL_AMBIENT, f); }),
                 "glGetMaterialfv");
  expectRejected(GL_INVALID_OPERATION, inside([&] { glGetMaterialiv(GL_FRONT, GL_AMBIENT, i); }),
                 "glGetMaterialiv");
  // glMaterial is allowed, and its errors are still its own.
  glBegin(GL_POINTS);
  glMaterialfv(GL_FRONT, GL_AMBIENT, v);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(ctx_.lighting.material[kFront].ambient, vec4(0.5f, 0.5f, 0.5f, 1));
  expectRejected(GL_INVALID_VALUE, inside([&] { glMaterialf(GL_FRONT, GL_SHININESS, 200); }),
                 "glMaterial 200");
}

TEST_F(LightApiTest, TheFirstErrorIsKept) {
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 100);         // INVALID_VALUE
  glLightf(GL_LIGHT0 + 0x100, GL_SPOT_CUTOFF, 10);  // INVALID_ENUM
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, NoCurrentContextDoesNothing) {
  setCurrentContext(nullptr);
  const GLfloat v[4] = {1, 1, 1, 1};
  GLfloat f[4] = {-7, -7, -7, -7};
  GLint i[4] = {-7, -7, -7, -7};
  glLightfv(GL_LIGHT0, GL_AMBIENT, v);
  glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1);
  glMaterialfv(GL_FRONT, GL_AMBIENT, v);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glShadeModel(GL_FLAT);
  glGetLightfv(GL_LIGHT0, GL_AMBIENT, f);
  glGetLightiv(GL_LIGHT0, GL_AMBIENT, i);
  glGetMaterialfv(GL_FRONT, GL_AMBIENT, f);
  glGetMaterialiv(GL_FRONT, GL_AMBIENT, i);
  EXPECT_EQ(f[0], -7.0f);
  EXPECT_EQ(i[0], -7);
  setCurrentContext(&ctx_);
  EXPECT_TRUE(sameLighting(ctx_.lighting, LightingAttrib{}));
}

// ---- materials between glBegin and glEnd, colour material -----------------------

TEST_F(LightApiTest, MaterialBetweenBeginAndEndMakesANewSnapshot) {
  const GLfloat red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
  glBegin(GL_TRIANGLES);
  glVertex3f(0, 0, 0);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glMaterialf(GL_BACK, GL_SHININESS, 5);  // no vertex in between: the same snapshot
  glVertex3f(1, 0, 0);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, blue);
  glVertex3f(0, 1, 0);
  const VertexBatch& b = ctx_.batch;
  ASSERT_EQ(b.materials.size(), 3u);
  EXPECT_EQ(b.materialIndex, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(b.materials[0][kFront].diffuse, vec4(0.8f, 0.8f, 0.8f, 1));
  EXPECT_EQ(b.materials[1][kFront].diffuse, vec4(1, 0, 0, 1));
  EXPECT_EQ(b.materials[1][kBack].shininess, 5.0f);
  EXPECT_EQ(b.materials[2][kBack].specular, vec4(0, 0, 1, 1));
  EXPECT_EQ(b.materials[2][kFront].diffuse, vec4(1, 0, 0, 1));
  const uint32_t back = vertex::kTrackBackShift;
  EXPECT_EQ(ctx_.lighting.beginEndMaterialMask, vertex::kTrackDiffuse | (vertex::kMaterialShininess << back) |
                                                    vertex::kTrackSpecular |
                                                    (vertex::kTrackSpecular << back));
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // The state after glEnd is the last material set.
  EXPECT_EQ(materialf(GL_FRONT, GL_DIFFUSE, 4), (V{1, 0, 0, 1}));
  EXPECT_EQ(materialf(GL_BACK, GL_SPECULAR, 4), (V{0, 0, 1, 1}));
  EXPECT_EQ(materialf(GL_BACK, GL_SHININESS, 1), (V{5}));
}

TEST_F(LightApiTest, EachBatchStartsItsOwnMaterialMask) {
  const GLfloat red[4] = {1, 0, 0, 1};
  glBegin(GL_POINTS);
  glMaterialfv(GL_BACK, GL_AMBIENT, red);
  glVertex3f(0, 0, 0);
  glEnd();
  glBegin(GL_POINTS);
  glVertex3f(0, 0, 0);
  EXPECT_EQ(ctx_.batch.materials.size(), 1u);  // no glMaterial: the mask is not read
  glMaterialfv(GL_FRONT, GL_AMBIENT, red);     // same value: a snapshot anyway, and a fresh mask
  EXPECT_EQ(ctx_.batch.materials.size(), 2u);
  EXPECT_EQ(ctx_.lighting.beginEndMaterialMask, uint32_t(vertex::kTrackAmbient));
  glEnd();
}

TEST_F(LightApiTest, ColorMaterialTracksTheCurrentColour) {
  glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  EXPECT_EQ(materialf(GL_FRONT, GL_DIFFUSE, 4), (V{0.8f, 0.8f, 0.8f, 1}));  // not enabled yet
  glEnable(GL_COLOR_MATERIAL);  // takes the current colour at once
  EXPECT_EQ(materialf(GL_FRONT, GL_DIFFUSE, 4), (V{0.1f, 0.2f, 0.3f, 0.4f}));
  const GLfloat grey[4] = {0.9f, 0.9f, 0.9f, 0.9f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);  // a tracked component: ignored, no error (Mesa)
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(materialf(GL_FRONT, GL_DIFFUSE, 4), (V{0.1f, 0.2f, 0.3f, 0.4f}));
  glMaterialfv(GL_BACK, GL_DIFFUSE, grey);  // not tracked: set
  EXPECT_EQ(materialf(GL_BACK, GL_DIFFUSE, 4), (V{0.9f, 0.9f, 0.9f, 0.9f}));
  glColorMaterial(GL_FRONT, GL_SPECULAR);  // the new component takes the colour at once
  EXPECT_EQ(materialf(GL_FRONT, GL_SPECULAR, 4), (V{0.1f, 0.2f, 0.3f, 0.4f}));
  glColor4f(0.5f, 0.6f, 0.7f, 0.8f);
  EXPECT_EQ(materialf(GL_FRONT, GL_SPECULAR, 4), (V{0.5f, 0.6f, 0.7f, 0.8f}));
  EXPECT_EQ(materialf(GL_FRONT, GL_DIFFUSE, 4), (V{0.1f, 0.2f, 0.3f, 0.4f}));  // no longer tracked
  glBegin(GL_POINTS);
  glColor4f(0.25f, 0.35f, 0.45f, 0.55f);
  glVertex2f(0, 0);
  glColor4f(0.3f, 0.3f, 0.3f, 0.3f);
  glEnd();  // the material after glEnd is the last colour
  EXPECT_EQ(materialf(GL_FRONT, GL_SPECULAR, 4), (V{0.3f, 0.3f, 0.3f, 0.3f}));
  glDisable(GL_COLOR_MATERIAL);
  glColor4f(0.7f, 0.7f, 0.7f, 0.7f);
  EXPECT_EQ(materialf(GL_FRONT, GL_SPECULAR, 4), (V{0.3f, 0.3f, 0.3f, 0.3f}));
  EXPECT_EQ(materialf(GL_BACK, GL_SPECULAR, 4), (V{0, 0, 0, 1}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(LightApiTest, StateChangesRebuildTheLightingConstants) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT3);
  glDisable(GL_LIGHT0);
  const vertex::VertexState& vs = ctx_.validate();
  ASSERT_NE(vs.lightingConstants, nullptr);
  ASSERT_EQ(vs.lightingConstants->lightCount, 1);
  EXPECT_EQ(vs.lightingConstants->lights[0].index, 3);
  glLightf(GL_LIGHT3, GL_SPOT_CUTOFF, 45);
  const vertex::VertexState& vs2 = ctx_.validate();
  EXPECT_TRUE(vs2.lightingConstants->lights[0].spot);
  EXPECT_NEAR(vs2.lightingConstants->lights[0].spotCosCutoff, std::cos(M_PI / 4), 1e-7);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  EXPECT_TRUE(ctx_.validate().lightingConstants->twoSide);
}

}  // namespace
