// The places where llvmpipe's lighting departs from the exact GL 2.1 equation,
// pinned to the 8-bit values llvmpipe (Mesa 22.3.6) draws. The values were
// measured with tests/vertex/probes/lighting_quirks_probe.c, which sets up the
// same states through the GL API; each case here builds that state directly
// and lights the one vertex with lightBatch.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pipeline/vertex_batch.h"
#include "state/attribs.h"
#include "state/lighting_attrib.h"
#include "vertex/light_constants.h"
#include "vertex/lighting_math.h"
#include "vertex/vertex_stage.h"

namespace {

using namespace glfixed;
using glm::vec3;
using glm::vec4;

struct Rgba {
  int r, g, b, a;
  bool operator==(const Rgba& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
};
std::ostream& operator<<(std::ostream& os, const Rgba& c) {
  return os << "(" << c.r << ", " << c.g << ", " << c.b << ", " << c.a << ")";
}

// The probe's reset(): light 0 directional along +z, white diffuse and
// specular, no ambient anywhere, a black material.
LightingAttrib probeState() {
  LightingAttrib la;
  la.lighting = true;
  la.model.ambient = vec4(0, 0, 0, 1);
  Light& l = la.light[0];
  l.enabled = true;
  l.ambient = vec4(0, 0, 0, 1);
  l.diffuse = vec4(1);
  l.specular = vec4(1);
  l.eyePosition = vec4(0, 0, 1, 0);
  for (Material& m : la.material) {
    m.ambient = m.diffuse = m.specular = m.emission = vec4(0, 0, 0, 1);
    m.shininess = 0;
  }
  return la;
}

inline int toByte(float v) { return static_cast<int>(std::rint(v * 255.0f)); }

// Lights one vertex at the origin (identity modelview) with normal n and
// returns the face's colour as llvmpipe stores it.
Rgba lightVertex(const LightingAttrib& la, vec3 n, int face = kFront) {
  TransformAttrib ta;
  vertex::LightingConstants k;
  vertex::buildLightingConstants(la, ta, k);
  VertexBatch batch;
  batch.reset(GL_TRIANGLES, la.material);
  batch.position.emplace_back(0, 0, 0, 1);
  batch.normal.push_back(n);
  batch.color.emplace_back(1, 1, 1, 1);
  batch.materialIndex.push_back(0);
  vertex::VertexState vs;
  vs.lighting = true;
  vs.lightingConstants = &k;
  vs.lightingAttrib = &la;
  vs.transformAttrib = &ta;
  ShadedVertices out;
  vertex::lightBatch(vs, batch, out);
  const vec4 c = out.primary[face][0];
  return Rgba{toByte(c.r), toByte(c.g), toByte(c.b), toByte(c.a)};
}

TEST(LightingQuirksTest, SpecularPowerIsGallivmsApproximation) {
  // n.h = n.z exactly (light and half vector are +z); colour = pow(n.z, s).
  // Every case rounds the other way with the exact power.
  struct Case {
    float x, s;
    int llvmpipe, exact;
  } cases[] = {{0.987513363f, 59, 122, 121},  {0.994659483f, 83, 164, 163},  {0.99561882f, 28, 225, 226},
               {0.99681735f, 119, 175, 174},  {0.997174561f, 78, 205, 204},  {0.990554512f, 92, 106, 107},
               {0.986421824f, 49, 130, 131},  {0.994244337f, 107, 137, 138}, {0.999715149f, 119, 247, 246},
               {0.995298624f, 128, 139, 140}, {0.994674623f, 100, 149, 150}, {0.998495996f, 70, 229, 230}};
  for (const Case& c : cases) {
    LightingAttrib la = probeState();
    la.material[kFront].specular = vec4(1);
    la.material[kFront].shininess = c.s;
    EXPECT_EQ(lightVertex(la, vec3(0, 0, c.x)), (Rgba{c.llvmpipe, c.llvmpipe, c.llvmpipe, 255}))
        << c.x << "^" << c.s;
    EXPECT_EQ(static_cast<int>(std::rint(std::pow(double(c.x), double(c.s)) * 255.0)), c.exact);
  }
}

TEST(LightingQuirksTest, PowOfZeroIsZeroEvenToTheZero) {
  EXPECT_EQ(vertex::lp::pow(0.0f, 0.0f), 0.0f);
  EXPECT_EQ(vertex::lp::pow(0.0f, 5.0f), 0.0f);
  EXPECT_EQ(vertex::lp::pow(0.25f, 0.0f), 1.0f);
  EXPECT_EQ(vertex::lp::pow(1.0f, 128.0f), 1.0f);
  EXPECT_EQ(vertex::lp::pow(0.5f, 1.0f), 0.5f);
  // Beyond 2^128 the result is infinite, as exp2 clamps its argument to 128.
  EXPECT_TRUE(std::isinf(vertex::lp::pow(2.5f, 128.0f)));
}

TEST(LightingQuirksTest, ShininessZeroEverywhereGivesFullSpecularWhereNDotLIsPositive) {
  LightingAttrib la = probeState();
  la.light[0].eyePosition = vec4(1, 0, 0.05f, 0);
  la.material[kFront].specular = vec4(0.4f, 0.6f, 0.8f, 1);
  // n.L > 0 but n.h < 0: the spec says 0^0 = 1 too here; llvmpipe agrees only
  // because every active shininess is 0 (no LIT at all).
  EXPECT_EQ(lightVertex(la, vec3(0.3f, 0, -0.9f)), (Rgba{102, 153, 204, 255}));
}

TEST(LightingQuirksTest, ShininessZeroBesideANonZeroOneIsZeroWhereNDotHIsNotPositive) {
  LightingAttrib la = probeState();
  la.light[0].eyePosition = vec4(1, 0, 0.05f, 0);
  la.material[kFront].specular = vec4(0.4f, 0.6f, 0.8f, 1);
  la.model.twoSide = true;
  la.material[kBack].shininess = 10;  // makes LIT run: pow(max(n.h, 0), 0)
  EXPECT_EQ(lightVertex(la, vec3(0.3f, 0, -0.9f)), (Rgba{0, 0, 0, 255}));       // pow(0, 0) = 0
  EXPECT_EQ(lightVertex(la, vec3(0.9f, 0, 0.1f)), (Rgba{102, 153, 204, 255}));  // pow(x > 0, 0) = 1
}

TEST(LightingQuirksTest, ShininessZeroWithAttenuationOrSpotIsNDotLToTheNDotL) {
  LightingAttrib la = probeState();
  la.light[0].eyePosition = vec4(0, 0, 2, 1);
  la.light[0].linearAttenuation = 0.5f;  // att = 1 / (1 + 0.5 * 2) = 0.5
  la.material[kFront].specular = vec4(1);
  EXPECT_EQ(lightVertex(la, vec3(0, 0, 0.5f)), (Rgba{90, 90, 90, 255}));  // 0.5 * 0.5^0.5
  EXPECT_EQ(lightVertex(la, vec3(0, 0, 0.2f)), (Rgba{92, 92, 92, 255}));  // 0.5 * 0.2^0.2
  LightingAttrib spot = probeState();
  spot.light[0].eyePosition = vec4(0, 0, 2, 1);
  spot.light[0].spotCutoff = 60;
  spot.material[kFront].specular = vec4(1);
  EXPECT_EQ(lightVertex(spot, vec3(0, 0, 0.3f)), (Rgba{178, 178, 178, 255}));  // 0.3^0.3
}

TEST(LightingQuirksTest, DirectionalSpotLightTestsTheLightDirection) {
  LightingAttrib la = probeState();
  la.material[kFront].diffuse = vec4(1);
  la.light[0].spotCutoff = 30;
  la.light[0].spotExponent = 20;
  la.light[0].eyeSpotDirection = vec3(0, 0, -1);
  EXPECT_EQ(lightVertex(la, vec3(0, 0, 1)), (Rgba{255, 255, 255, 255}));
  la.light[0].eyeSpotDirection = vec3(0, 0, 1);  // the cone excludes the light's own direction
  EXPECT_EQ(lightVertex(la, vec3(0, 0, 1)), (Rgba{0, 0, 0, 255}));
  la.light[0].eyeSpotDirection = vec3(0.3f, 0, -1);  // 0.958^20
  EXPECT_EQ(lightVertex(la, vec3(0, 0, 1)), (Rgba{108, 108, 108, 255}));
}

TEST(LightingQuirksTest, NanClampsToOneAndInfinitiesToTheirEnds) {
  LightingAttrib la = probeState();
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  la.material[kFront].emission = vec4(nan, inf, -inf, 1);
  la.material[kFront].diffuse = vec4(0, 0, 0, nan);
  EXPECT_EQ(lightVertex(la, vec3(0, 0, 1)), (Rgba{255, 255, 0, 255}));
  EXPECT_EQ(vertex::lp::clampColor(nan), 1.0f);
  EXPECT_EQ(vertex::lp::clampColor(-inf), 0.0f);
}

TEST(LightingQuirksTest, PerVertexBackMaterialHasRedOnlyProducts) {
  // Two-sided lighting, glMaterial(GL_FRONT / GL_BACK, GL_DIFFUSE) between
  // glBegin and glEnd, a back face lit from behind: the back diffuse product
  // is (0.9 * 1, front's 0.4, front's 0.6), plus the back ambient.
  LightingAttrib la = probeState();
  la.model.twoSide = true;
  la.light[0].eyePosition = vec4(0, 0, -1, 0);
  la.light[0].ambient = vec4(1);
  la.material[kBack].ambient = vec4(0.5f, 0.05f, 0.05f, 1);
  TransformAttrib ta;
  vertex::LightingConstants k;
  vertex::buildLightingConstants(la, ta, k);
  VertexBatch batch;
  batch.reset(GL_TRIANGLES, la.material);
  MaterialPair changed = la.material;
  changed[kFront].diffuse = vec4(0.2f, 0.4f, 0.6f, 1);
  changed[kBack].diffuse = vec4(0.9f, 0.1f, 0.1f, 1);
  batch.materials.push_back(changed);
  la.beginEndMaterialMask = vertex::kTrackDiffuse | (vertex::kTrackDiffuse << vertex::kTrackBackShift);
  batch.position.emplace_back(0, 0, 0, 1);
  batch.normal.emplace_back(0, 0, 1);
  batch.color.emplace_back(1, 1, 1, 1);
  batch.materialIndex.push_back(1);
  vertex::VertexState vs;
  vs.lighting = true;
  vs.lightingConstants = &k;
  vs.lightingAttrib = &la;
  vs.transformAttrib = &ta;
  ShadedVertices out;
  vertex::lightBatch(vs, batch, out);
  const vec4 c = out.primary[kBack][0];
  EXPECT_EQ((Rgba{toByte(c.r), toByte(c.g), toByte(c.b), toByte(c.a)}), (Rgba{255, 115, 166, 255}));
  // With equal front and back materials the quirk is invisible.
  changed[kBack].diffuse = changed[kFront].diffuse;
  batch.materials[1] = changed;
  vertex::lightBatch(vs, batch, out);
  const vec4 d = out.primary[kBack][0];
  EXPECT_EQ((Rgba{toByte(d.r), toByte(d.g), toByte(d.b), toByte(d.a)}),
            (Rgba{toByte(0.5f + 0.2f), toByte(0.05f + 0.4f), toByte(0.05f + 0.6f), 255}));
}

}  // namespace
