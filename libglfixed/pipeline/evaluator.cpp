// The evaluator arithmetic, every step a single-precision operation rounded
// on its own (the build turns off contraction into fused multiply-adds), in
// the order of Mesa 22.3's math/m_eval.c and vbo/vbo_exec_eval.c.
#include "pipeline/evaluator.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glfixed::pipeline {

namespace {

// 1/i as a float, for the binomial coefficients of Horner's scheme.
float inverse(int i) { return 1.0f / static_cast<float>(i); }

// One de Casteljau level along a row of n values: e[j] = (1-t) e[j] + t e[j+1].
void lerpLevel(float* e, int n, float t, float ts) {
  for (int j = 0; j + 1 < n; ++j) e[j] = ts * e[j] + t * e[j + 1];
}

// One component of the de Casteljau evaluation (see bezierSurfaceWithPartials).
void deCasteljauComponent(const float* points, int dim, int k, int uorder, int vorder, float u, float v,
                          float* out, float* du, float* dv) {
  const float us = 1.0f - u, vs = 1.0f - v;
  std::array<float, kMaxEvalOrder * kMaxEvalOrder> grid;
  const int stride = vorder;  // grid(i, j) at i * vorder + j, whatever is left of it
  auto g = [&](int i, int j) -> float& { return grid[i * stride + j]; };
  for (int i = 0; i < uorder; ++i)
    for (int j = 0; j < vorder; ++j) g(i, j) = points[(i * vorder + j) * dim + k];

  // Bilinear levels (u first, then v) until the shorter direction has 2 left.
  int a = uorder, b = vorder;
  for (int level = 2; level < std::min(uorder, vorder); ++level, --a, --b)
    for (int i = 0; i + 1 < a; ++i)
      for (int j = 0; j + 1 < b; ++j)
        g(i, j) = vs * (us * g(i, j) + u * g(i + 1, j)) + v * (us * g(i, j + 1) + u * g(i + 1, j + 1));

  if (a == 2 && b == 2) {
    *du = vs * (g(1, 0) - g(0, 0)) + v * (g(1, 1) - g(0, 1));
    *dv = us * (g(0, 1) - g(0, 0)) + u * (g(1, 1) - g(1, 0));
    *out = us * (vs * g(0, 0) + v * g(0, 1)) + u * (vs * g(1, 0) + v * g(1, 1));
  } else if (a == 2) {  // longer along v: a difference row and a point row, reduced along v
    std::array<float, kMaxEvalOrder> d, p;
    for (int j = 0; j < b; ++j) {
      d[j] = g(1, j) - g(0, j);
      p[j] = us * g(0, j) + u * g(1, j);
    }
    for (int n = b; n > 2; --n) {
      lerpLevel(d.data(), n, v, vs);
      lerpLevel(p.data(), n, v, vs);
    }
    *du = vs * d[0] + v * d[1];
    *dv = p[1] - p[0];
    *out = vs * p[0] + v * p[1];
  } else {  // longer along u
    std::array<float, kMaxEvalOrder> d, p;
    for (int i = 0; i < a; ++i) {
      d[i] = g(i, 1) - g(i, 0);
      p[i] = vs * g(i, 0) + v * g(i, 1);
    }
    for (int n = a; n > 2; --n) {
      lerpLevel(d.data(), n, u, us);
      lerpLevel(p.data(), n, u, us);
    }
    *du = p[1] - p[0];
    *dv = us * d[0] + u * d[1];
    *out = us * p[0] + u * p[1];
  }
}

// The enabled map of the highest priority among `slots` (GL 2.1 §5.1: the
// map of the most components of a kind is used), or -1.
template <size_t N>
int firstEnabled(const std::array<bool, kEvalTargets>& enabled, const int (&slots)[N]) {
  for (int s : slots)
    if (enabled[s]) return s;
  return -1;
}

constexpr int kColorSlot = GL_MAP1_COLOR_4 - GL_MAP1_COLOR_4;
constexpr int kNormalSlot = GL_MAP1_NORMAL - GL_MAP1_COLOR_4;
constexpr int kTexCoordSlots[] = {
    GL_MAP1_TEXTURE_COORD_4 - GL_MAP1_COLOR_4, GL_MAP1_TEXTURE_COORD_3 - GL_MAP1_COLOR_4,
    GL_MAP1_TEXTURE_COORD_2 - GL_MAP1_COLOR_4, GL_MAP1_TEXTURE_COORD_1 - GL_MAP1_COLOR_4};
constexpr int kVertexSlots[] = {GL_MAP1_VERTEX_4 - GL_MAP1_COLOR_4, GL_MAP1_VERTEX_3 - GL_MAP1_COLOR_4};

int components(int slot) { return evalComponents(GL_MAP1_COLOR_4 + slot); }

// Evaluates map `slot` into out (which keeps its initial values past the map's size).
void curveOf(const EvalMap& m, int slot, float u, float* out) {
  bezierCurve(m.points.data(), components(slot), components(slot), m.uorder, unitParameter(u, m.u1, m.u2),
              out);
}
void surfaceOf(const EvalMap& m, int slot, float u, float v, float* out) {
  bezierSurface(m.points.data(), components(slot), m.uorder, m.vorder, unitParameter(u, m.u1, m.u2),
                unitParameter(v, m.v1, m.v2), out);
}

}  // namespace

void bezierCurve(const float* points, int stride, int dim, int order, float t, float* out) {
  if (order < 2) {
    for (int k = 0; k < dim; ++k) out[k] = points[k];
    return;
  }
  const float s = 1.0f - t;
  float binomial = static_cast<float>(order - 1);
  for (int k = 0; k < dim; ++k) out[k] = s * points[k] + binomial * t * points[stride + k];
  float tPower = t * t;
  for (int i = 2; i < order; ++i, tPower *= t) {
    binomial *= static_cast<float>(order - i);
    binomial *= inverse(i);
    const float* p = points + i * stride;
    for (int k = 0; k < dim; ++k) out[k] = s * out[k] + binomial * tPower * p[k];
  }
}

void bezierSurface(const float* points, int dim, int uorder, int vorder, float u, float v, float* out) {
  std::array<float, kMaxEvalOrder * 4> curve;  // the control points of one curve on the surface
  if (vorder > uorder) {
    if (uorder < 2) return bezierCurve(points, dim, dim, vorder, v, out);
    for (int j = 0; j < vorder; ++j)
      bezierCurve(points + j * dim, vorder * dim, dim, uorder, u, &curve[j * dim]);
    bezierCurve(curve.data(), dim, dim, vorder, v, out);
  } else {
    if (vorder < 2) return bezierCurve(points, dim, dim, uorder, u, out);
    for (int i = 0; i < uorder; ++i)
      bezierCurve(points + i * vorder * dim, dim, dim, vorder, v, &curve[i * dim]);
    bezierCurve(curve.data(), dim, dim, uorder, u, out);
  }
}

void bezierSurfaceWithPartials(const float* points, int dim, int uorder, int vorder, float u, float v,
                               float* out, float* du, float* dv) {
  if (uorder < 2 || vorder < 2) {
    // Mesa reads past the control points here; a constant direction has no
    // derivative, so the point comes from Horner and that partial is 0.
    // (A zero partial makes the auto normal (0, 0, 0); Mesa's is undefined.)
    bezierSurface(points, dim, uorder, vorder, u, v, out);
    for (int k = 0; k < dim; ++k) du[k] = dv[k] = 0.0f;
    return;
  }
  for (int k = 0; k < dim; ++k)
    deCasteljauComponent(points, dim, k, uorder, vorder, u, v, &out[k], &du[k], &dv[k]);
}

float unitParameter(float u, float u1, float u2) {
  const float scale = 1.0f / (u2 - u1);
  return (u - u1) * scale;
}

glm::vec3 autoNormal(const float* point, const float* du, const float* dv, int dim) {
  float a[3] = {du[0], du[1], du[2]}, b[3] = {dv[0], dv[1], dv[2]};
  if (dim == 4) {  // d(x/w) times w^2: x' w - w' x
    for (int c = 0; c < 3; ++c) {
      a[c] = du[c] * point[3] - du[3] * point[c];
      b[c] = dv[c] * point[3] - dv[3] * point[c];
    }
  }
  glm::vec3 n(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
  const float lengthSquared = n.x * n.x + n.y * n.y + n.z * n.z;
  if (lengthSquared != 0.0f) {
    const float inverseLength = 1.0f / std::sqrt(lengthSquared);
    n = glm::vec3(n.x * inverseLength, n.y * inverseLength, n.z * inverseLength);
  }
  return n;
}

EvaluatedVertex evaluate1(const EvalAttrib& state, const EvalMaps& maps, float u) {
  EvaluatedVertex e;
  const auto& on = state.map1Enabled;
  if (on[kColorSlot]) {
    e.hasColor = true;
    curveOf(maps.map1[kColorSlot], kColorSlot, u, &e.color[0]);
  }
  if (int s = firstEnabled(on, kTexCoordSlots); s >= 0) {
    e.hasTexCoord = true;
    curveOf(maps.map1[s], s, u, &e.texCoord[0]);
  }
  if (on[kNormalSlot]) {
    e.hasNormal = true;
    curveOf(maps.map1[kNormalSlot], kNormalSlot, u, &e.normal[0]);
  }
  if (int s = firstEnabled(on, kVertexSlots); s >= 0) {
    e.hasVertex = true;
    curveOf(maps.map1[s], s, u, &e.position[0]);
  }
  return e;
}

EvaluatedVertex evaluate2(const EvalAttrib& state, const EvalMaps& maps, float u, float v) {
  EvaluatedVertex e;
  const auto& on = state.map2Enabled;
  if (on[kColorSlot]) {
    e.hasColor = true;
    surfaceOf(maps.map2[kColorSlot], kColorSlot, u, v, &e.color[0]);
  }
  if (int s = firstEnabled(on, kTexCoordSlots); s >= 0) {
    e.hasTexCoord = true;
    surfaceOf(maps.map2[s], s, u, v, &e.texCoord[0]);
  }
  if (on[kNormalSlot]) {
    e.hasNormal = true;
    surfaceOf(maps.map2[kNormalSlot], kNormalSlot, u, v, &e.normal[0]);
  }
  const int s = firstEnabled(on, kVertexSlots);
  if (s < 0) return e;
  e.hasVertex = true;
  const EvalMap& m = maps.map2[s];
  const int dim = components(s);
  if (!state.autoNormal) {
    surfaceOf(m, s, u, v, &e.position[0]);
    return e;
  }
  // GL_AUTO_NORMAL: the point and its partials together; the normal replaces
  // a MAP2_NORMAL one (§5.1).
  float du[4], dv[4];
  bezierSurfaceWithPartials(m.points.data(), dim, m.uorder, m.vorder, unitParameter(u, m.u1, m.u2),
                            unitParameter(v, m.v1, m.v2), &e.position[0], du, dv);
  e.hasNormal = true;
  e.normal = autoNormal(&e.position[0], du, dv, dim);
  return e;
}

}  // namespace glfixed::pipeline
