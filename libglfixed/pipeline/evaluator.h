// Evaluators (GL 2.1 §5.1): the Bézier arithmetic behind glEvalCoord, done in
// single precision in the order Mesa's does it, so that an evaluated vertex
// is the same float on both (reference/MESA_FACTS.md, "Evaluators").
#pragma once

#include <glm/glm.hpp>

#include "state/eval_attrib.h"

namespace glfixed::pipeline {

// The point at t in [0,1] of the Bézier curve of `order` control points of
// `dim` values each, `stride` floats apart: Horner's scheme in powers of t
// and 1 - t, the binomial coefficients built up as it goes.
void bezierCurve(const float* points, int stride, int dim, int order, float t, float* out);

// The point at (u, v) of a tensor-product surface (EvalMap layout): one curve
// per row of control points along v, then the curve of those points along u;
// when vorder > uorder, along u first, then along v (Mesa's order, which
// decides the roundings).
void bezierSurface(const float* points, int dim, int uorder, int vorder, float u, float v, float* out);

// The point and the two partial derivative directions at (u, v), by de
// Casteljau's algorithm. The derivatives are not scaled by the order or the
// domain (only their directions are used, for GL_AUTO_NORMAL). Needs
// uorder, vorder >= 2; a direction of order 1 gives a zero derivative.
void bezierSurfaceWithPartials(const float* points, int dim, int uorder, int vorder, float u, float v,
                               float* out, float* du, float* dv);

// What one glEvalCoord generates from the enabled maps (GL 2.1 §5.1): the
// highest-dimension texture and vertex maps win, as the spec says; colour
// index maps are stored but generate nothing (RGBA only).
struct EvaluatedVertex {
  bool hasVertex = false;
  glm::vec4 position{0, 0, 0, 1};  // a VERTEX_3 map gives w = 1
  bool hasColor = false;
  glm::vec4 color{0, 0, 0, 1};
  bool hasNormal = false;  // MAP*_NORMAL, or GL_AUTO_NORMAL with a 2D vertex map
  glm::vec3 normal{0, 0, 0};
  bool hasTexCoord = false;
  glm::vec4 texCoord{0, 0, 0, 1};  // (s, t, 0, 1) from a TEXTURE_COORD_2 map
};

// The map parameter mapped onto [0,1]: (u - u1) * (1 / (u2 - u1)), in float.
float unitParameter(float u, float u1, float u2);

EvaluatedVertex evaluate1(const EvalAttrib& state, const EvalMaps& maps, float u);
EvaluatedVertex evaluate2(const EvalAttrib& state, const EvalMaps& maps, float u, float v);

// The surface normal GL_AUTO_NORMAL gives from a point and its two partial
// derivative directions (dim 3, or 4 for a rational VERTEX_4 map: the
// derivatives of x/w taken without the division, which only scales them).
glm::vec3 autoNormal(const float* point, const float* du, const float* dv, int dim);

}  // namespace glfixed::pipeline
