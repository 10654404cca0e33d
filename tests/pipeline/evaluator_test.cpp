// The evaluator arithmetic (pipeline/evaluator.h) against a double-precision
// oracle of the Bernstein form of GL 2.1 §5.1: curve and surface points, the
// partial derivatives behind GL_AUTO_NORMAL, the rational normal, and which
// maps evaluate1/evaluate2 use. (That the floats are Mesa's own is checked
// through the pixels of the reference scenes eval_*.)
#include "pipeline/evaluator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace glfixed::pipeline {
namespace {

double binomial(int n, int i) {
  double r = 1;
  for (int k = 1; k <= i; ++k) r = r * (n - i + k) / k;
  return r;
}
// B_i^n(t) and its derivative.
double bernstein(int n, int i, double t) { return binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i); }
double bernsteinDerivative(int n, int i, double t) {
  if (n == 0) return 0;
  double a = i > 0 ? bernstein(n - 1, i - 1, t) : 0;
  double b = i < n ? bernstein(n - 1, i, t) : 0;
  return n * (a - b);
}

// Surface value and partials in double, points in EvalMap layout.
struct Oracle {
  std::vector<double> p, du, dv;
};
Oracle surfaceOracle(const std::vector<float>& pts, int dim, int uorder, int vorder, double u, double v) {
  Oracle o{std::vector<double>(dim), std::vector<double>(dim), std::vector<double>(dim)};
  for (int i = 0; i < uorder; ++i)
    for (int j = 0; j < vorder; ++j)
      for (int k = 0; k < dim; ++k) {
        const double c = pts[(i * vorder + j) * dim + k];
        o.p[k] += bernstein(uorder - 1, i, u) * bernstein(vorder - 1, j, v) * c;
        o.du[k] += bernsteinDerivative(uorder - 1, i, u) * bernstein(vorder - 1, j, v) * c;
        o.dv[k] += bernstein(uorder - 1, i, u) * bernsteinDerivative(vorder - 1, j, v) * c;
      }
  return o;
}

std::vector<float> randomPoints(std::mt19937& rng, int n) {
  std::uniform_real_distribution<float> d(-2.0f, 2.0f);
  std::vector<float> v(n);
  for (float& x : v) x = d(rng);
  return v;
}

// Float rounding grows with the order (measured: under 2e-6 for control
// points in [-2, 2] up to order 30); a wrong coefficient is off by far more.
double tolerance(int order) { return 1e-6 * (order + 2); }

TEST(Evaluator, CurveMatchesTheBernsteinForm) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> t01(0.0f, 1.0f);
  for (int order = 1; order <= kMaxEvalOrder; ++order)
    for (int dim = 1; dim <= 4; ++dim)
      for (int trial = 0; trial < 20; ++trial) {
        // stride dim + 1: the point after each is never read
        std::vector<float> pts = randomPoints(rng, order * (dim + 1));
        const float t = trial == 0 ? 0.0f : trial == 1 ? 1.0f : t01(rng);
        float out[4] = {-99, -99, -99, -99};
        bezierCurve(pts.data(), dim + 1, dim, order, t, out);
        for (int k = 0; k < dim; ++k) {
          double want = 0;
          for (int i = 0; i < order; ++i) want += bernstein(order - 1, i, t) * pts[i * (dim + 1) + k];
          ASSERT_NEAR(out[k], want, tolerance(order)) << "order " << order << " dim " << dim << " t " << t;
        }
        for (int k = dim; k < 4; ++k) EXPECT_EQ(out[k], -99.0f) << "wrote past dim";
      }
}

TEST(Evaluator, CurveEndpointsAreTheEndControlPoints) {
  const float pts[4] = {0.3f, -1.7f, 2.5f, 0.9f};
  float out;
  bezierCurve(pts, 1, 1, 4, 0.0f, &out);
  EXPECT_EQ(out, 0.3f);
  bezierCurve(pts, 1, 1, 4, 1.0f, &out);
  EXPECT_FLOAT_EQ(out, 0.9f);
}

const int kShapes[][2] = {{1, 1}, {1, 4}, {4, 1}, {2, 2}, {2, 5},  {5, 2},  {3, 3},  {3, 6},
                          {6, 3}, {4, 4}, {7, 4}, {4, 7}, {10, 3}, {2, 12}, {12, 12}};

TEST(Evaluator, SurfaceMatchesTheBernsteinForm) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> t01(0.0f, 1.0f);
  for (const auto& shape : kShapes)
    for (int dim : {1, 3, 4})
      for (int trial = 0; trial < 25; ++trial) {
        const int uo = shape[0], vo = shape[1];
        std::vector<float> pts = randomPoints(rng, uo * vo * dim);
        const float u = t01(rng), v = t01(rng);
        float out[4];
        bezierSurface(pts.data(), dim, uo, vo, u, v, out);
        Oracle o = surfaceOracle(pts, dim, uo, vo, u, v);
        for (int k = 0; k < dim; ++k)
          ASSERT_NEAR(out[k], o.p[k], tolerance(uo + vo)) << uo << "x" << vo << " dim " << dim;
      }
}

// de Casteljau: the same point, and partials that are the true ones divided
// by (order - 1) (Mesa leaves them unscaled: only their directions count).
TEST(Evaluator, PartialsMatchTheBernsteinDerivatives) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> t01(0.0f, 1.0f);
  for (const auto& shape : kShapes) {
    const int uo = shape[0], vo = shape[1];
    if (uo < 2 || vo < 2) continue;
    for (int dim : {3, 4})
      for (int trial = 0; trial < 25; ++trial) {
        std::vector<float> pts = randomPoints(rng, uo * vo * dim);
        const float u = trial == 0 ? 0.0f : t01(rng), v = trial == 0 ? 1.0f : t01(rng);
        float out[4], du[4], dv[4];
        bezierSurfaceWithPartials(pts.data(), dim, uo, vo, u, v, out, du, dv);
        Oracle o = surfaceOracle(pts, dim, uo, vo, u, v);
        const double tol = tolerance(uo + vo) * 4;
        for (int k = 0; k < dim; ++k) {
          SCOPED_TRACE(::testing::Message() << uo << "x" << vo << " dim " << dim << " k " << k);
          ASSERT_NEAR(out[k], o.p[k], tol);
          ASSERT_NEAR(du[k] * (uo - 1), o.du[k], tol * uo);
          ASSERT_NEAR(dv[k] * (vo - 1), o.dv[k], tol * vo);
        }
      }
  }
}

TEST(Evaluator, OrderOneSurfaceHasNoPartialInThatDirection) {
  const std::vector<float> pts = {0, 0, 0, 1, 2, 3, 2, 2, 2};  // 1 x 3, dim 3
  float out[3], du[3], dv[3];
  bezierSurfaceWithPartials(pts.data(), 3, 1, 3, 0.5f, 0.5f, out, du, dv);
  EXPECT_FLOAT_EQ(out[0], 1.0f);  // 0.25*0 + 0.5*1 + 0.25*2
  for (int k = 0; k < 3; ++k) EXPECT_EQ(du[k], 0.0f);
  EXPECT_EQ(autoNormal(out, du, dv, 3), glm::vec3(0.0f));
}

// The auto normal is the unit normal of the surface x/w, y/w, z/w.
TEST(Evaluator, AutoNormalIsTheUnitSurfaceNormal) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> t01(0.05f, 0.95f), w(0.5f, 2.0f);
  for (int dim : {3, 4})
    for (int trial = 0; trial < 200; ++trial) {
      const int uo = 2 + trial % 4, vo = 2 + (trial / 4) % 4;
      std::vector<float> pts = randomPoints(rng, uo * vo * dim);
      if (dim == 4)
        for (int i = 0; i < uo * vo; ++i) pts[i * 4 + 3] = w(rng);
      const float u = t01(rng), v = t01(rng);
      float out[4], du[4], dv[4];
      bezierSurfaceWithPartials(pts.data(), dim, uo, vo, u, v, out, du, dv);
      const glm::vec3 n = autoNormal(out, du, dv, dim);
      // oracle: derivatives of the projected surface, in double
      Oracle o = surfaceOracle(pts, dim, uo, vo, u, v);
      double a[3], b[3];
      for (int c = 0; c < 3; ++c) {
        if (dim == 3) {
          a[c] = o.du[c];
          b[c] = o.dv[c];
        } else {
          a[c] = (o.du[c] * o.p[3] - o.du[3] * o.p[c]) / (o.p[3] * o.p[3]);
          b[c] = (o.dv[c] * o.p[3] - o.dv[3] * o.p[c]) / (o.p[3] * o.p[3]);
        }
      }
      double want[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const double len = std::sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
      if (len < 1e-3) continue;  // nearly degenerate: the direction is ill-conditioned
      // w^2 > 0 and the unscaled partials keep the direction
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(n[c], want[c] / len, 2e-3) << "dim " << dim << " trial " << trial;
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    }
}

TEST(Evaluator, UnitParameterMapsTheDomainOntoZeroOne) {
  EXPECT_EQ(unitParameter(2.0f, 2.0f, 6.0f), 0.0f);
  EXPECT_EQ(unitParameter(6.0f, 2.0f, 6.0f), 1.0f);
  EXPECT_EQ(unitParameter(3.0f, 2.0f, 6.0f), 0.25f);
  EXPECT_EQ(unitParameter(0.25f, 1.0f, 0.0f), 0.75f);  // a reversed domain
  // (u - u1) times the float reciprocal of (u2 - u1), not a division
  EXPECT_EQ(unitParameter(0.1f, 0.0f, 0.3f), 0.1f * (1.0f / 0.3f));
}

EvalMaps mapsWith(int dimensionality, GLenum target, std::vector<float> points, int uorder, int vorder = 1) {
  EvalMaps m;
  EvalMap& map = *m.find(target);
  map.uorder = uorder;
  map.vorder = dimensionality == 2 ? vorder : 1;
  map.points = std::move(points);
  return m;
}

TEST(Evaluator, EvaluateUsesTheEnabledMapsOnly) {
  EvalAttrib s;
  EvalMaps maps;
  EvaluatedVertex e = evaluate1(s, maps, 0.5f);
  EXPECT_FALSE(e.hasVertex || e.hasColor || e.hasNormal || e.hasTexCoord);
  // the initial maps: a constant control point each
  s.map1Enabled[evalSlot(GL_MAP1_VERTEX_4)] = true;
  s.map1Enabled[evalSlot(GL_MAP1_COLOR_4)] = true;
  s.map1Enabled[evalSlot(GL_MAP1_NORMAL)] = true;
  s.map1Enabled[evalSlot(GL_MAP1_TEXTURE_COORD_3)] = true;
  s.map1Enabled[evalSlot(GL_MAP1_INDEX)] = true;
  e = evaluate1(s, maps, 0.7f);
  EXPECT_TRUE(e.hasVertex && e.hasColor && e.hasNormal && e.hasTexCoord);
  EXPECT_EQ(e.position, glm::vec4(0, 0, 0, 1));
  EXPECT_EQ(e.color, glm::vec4(1, 1, 1, 1));
  EXPECT_EQ(e.normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(e.texCoord, glm::vec4(0, 0, 0, 1));
}

TEST(Evaluator, TheMapOfMostComponentsWins) {
  EvalAttrib s;
  EvalMaps maps = mapsWith(1, GL_MAP1_VERTEX_3, {1, 2, 3, 1, 2, 3}, 2);
  *maps.find(GL_MAP1_VERTEX_4) = EvalMap{2, 1, 0, 1, 0, 1, {4, 5, 6, 2, 4, 5, 6, 2}};
  *maps.find(GL_MAP1_TEXTURE_COORD_1) = EvalMap{1, 1, 0, 1, 0, 1, {7}};
  *maps.find(GL_MAP1_TEXTURE_COORD_2) = EvalMap{1, 1, 0, 1, 0, 1, {8, 9}};
  s.map1Enabled[evalSlot(GL_MAP1_VERTEX_3)] = true;
  s.map1Enabled[evalSlot(GL_MAP1_TEXTURE_COORD_1)] = true;
  EvaluatedVertex e = evaluate1(s, maps, 0.5f);
  EXPECT_EQ(e.position, glm::vec4(1, 2, 3, 1));
  EXPECT_EQ(e.texCoord, glm::vec4(7, 0, 0, 1));
  s.map1Enabled[evalSlot(GL_MAP1_VERTEX_4)] = true;
  s.map1Enabled[evalSlot(GL_MAP1_TEXTURE_COORD_2)] = true;
  e = evaluate1(s, maps, 0.5f);
  EXPECT_EQ(e.position, glm::vec4(4, 5, 6, 2));
  EXPECT_EQ(e.texCoord, glm::vec4(8, 9, 0, 1));
}

TEST(Evaluator, AutoNormalReplacesTheNormalMap) {
  EvalAttrib s;
  // the plane z = 0 over [0,1]^2 with u along x, v along y: normal +z
  EvalMaps maps = mapsWith(2, GL_MAP2_VERTEX_3, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0}, 2, 2);
  *maps.find(GL_MAP2_NORMAL) = EvalMap{1, 1, 0, 1, 0, 1, {1, 0, 0}};
  s.map2Enabled[evalSlot(GL_MAP2_VERTEX_3)] = true;
  s.map2Enabled[evalSlot(GL_MAP2_NORMAL)] = true;
  EvaluatedVertex e = evaluate2(s, maps, 0.25f, 0.5f);
  EXPECT_EQ(e.position, glm::vec4(0.25f, 0.5f, 0, 1));
  EXPECT_EQ(e.normal, glm::vec3(1, 0, 0));
  s.autoNormal = true;
  e = evaluate2(s, maps, 0.25f, 0.5f);
  EXPECT_EQ(e.position, glm::vec4(0.25f, 0.5f, 0, 1));
  EXPECT_EQ(e.normal, glm::vec3(0, 0, 1));
  // GL_AUTO_NORMAL does nothing for 1D maps or without a vertex map
  s.map2Enabled[evalSlot(GL_MAP2_VERTEX_3)] = false;
  e = evaluate2(s, maps, 0.25f, 0.5f);
  EXPECT_FALSE(e.hasVertex);
  EXPECT_EQ(e.normal, glm::vec3(1, 0, 0));
}

}  // namespace
}  // namespace glfixed::pipeline
