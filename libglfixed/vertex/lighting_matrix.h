// What the lighting stage needs to know about the modelview matrix, derived the
// way Mesa derives it (src/mesa/math/m_matrix.c), because the reference's
// normals and light vectors are computed from Mesa's single-precision inverse:
//   - its classification (identity, 2D/3D without rotation, 2D/3D, general),
//     which picks the inversion formula and says whether the matrix preserves
//     lengths (rotations and translations within 1e-6);
//   - its inverse, by the formula the class picks (a transpose for rotations,
//     reciprocals for scales, cofactors for other affine matrices, Gaussian
//     elimination for the rest);
//   - the GL_RESCALE_NORMAL factor 1/sqrt(m31^2 + m32^2 + m33^2) of GL 2.1
//     §2.11.3, from the inverse's third row, or 1 for a length-preserving matrix.
//
// Mesa keeps classification flags while matrices are built (glRotate marks a
// rotation without testing it); this module classifies from the matrix values
// alone, as Mesa does after glLoadMatrix or glMultMatrix. The two agree for
// matrices built from rotations, translations and non-uniform scales.
#pragma once

#include <glm/glm.hpp>

namespace glfixed::vertex {

struct ModelviewAnalysis {
  bool lengthPreserving = true;  // only rotations and translations
  bool invertible = true;
  glm::mat4 inverse{1};        // Mesa's inverse (identity if singular)
  float normalRescale = 1.0f;  // GL_RESCALE_NORMAL factor for eye-space normals
};

ModelviewAnalysis analyseModelview(const glm::mat4& modelview);

// TRANSFORM_POINT of Mesa's macros: m * p, each row summed left to right.
glm::vec4 transformPointLikeMesa(const glm::mat4& m, const glm::vec4& p);
// TRANSFORM_DIRECTION: the upper 3x3 of m times d.
glm::vec3 transformDirectionLikeMesa(const glm::mat4& m, const glm::vec3& d);
// TRANSFORM_NORMAL: the row vector n times the upper 3x3 of m (m^T n).
glm::vec3 transformNormalLikeMesa(const glm::mat4& m, const glm::vec3& n);

}  // namespace glfixed::vertex
