// Mesa's modelview classification and inverse (m_matrix.c), re-derived: see
// lighting_matrix.h for why the lighting stage needs Mesa's rounding here.
#include "vertex/lighting_matrix.h"

#include <cmath>
#include <utility>

namespace glfixed::vertex {

namespace {

// m[col * 4 + row], column-major like GL.
using Array16 = float[16];

inline float at(const glm::mat4& m, int row, int col) { return m[col][row]; }
inline float& at(glm::mat4& m, int row, int col) { return m[col][row]; }

enum class MatrixType { kGeneral, kIdentity, k3dNoRot, kPerspective, k2d, k2dNoRot, k3d };

struct Flags {
  bool translation = false, rotation = false, uniformScale = false, generalScale = false;
  bool general3d = false, general = false;
};

inline float sq(float x) { return x * x; }

// analyse_from_scratch: which entries are exactly 0 and 1 decides the type;
// dot products within 1e-6 decide scale and rotation.
MatrixType classify(const glm::mat4& mm, Flags& f) {
  const float* m = &mm[0][0];
  auto zero = [&](int i) { return m[i] == 0.0f; };
  auto one = [&](int i) { return m[i] == 1.0f; };
  auto allZero = [&](std::initializer_list<int> idx) {
    for (int i : idx)
      if (!zero(i)) return false;
    return true;
  };
  const bool bottomRow = allZero({3, 7, 11}) && one(15);
  if (!allZero({12, 13, 14})) f.translation = true;

  const bool identity =
      one(0) && one(5) && one(10) && one(15) && allZero({1, 2, 3, 4, 6, 7, 8, 9, 11, 12, 13, 14});
  if (identity) return MatrixType::kIdentity;
  const bool is2dNoRot = allZero({1, 2, 4, 6, 8, 9, 14}) && one(10) && bottomRow;
  if (is2dNoRot) {
    if (!(one(0) && one(5))) f.generalScale = true;
    return MatrixType::k2dNoRot;
  }
  const bool is2d = allZero({2, 6, 8, 9, 14}) && one(10) && bottomRow;
  if (is2d) {
    const float mm0 = m[0] * m[0] + m[1] * m[1];
    const float m4m4 = m[4] * m[4] + m[5] * m[5];
    const float mm4 = m[0] * m[4] + m[1] * m[5];
    if (sq(mm0 - 1) > sq(1e-6f) || sq(m4m4 - 1) > sq(1e-6f)) f.generalScale = true;
    if (sq(mm4) > sq(1e-6f))
      f.general3d = true;
    else
      f.rotation = true;
    return MatrixType::k2d;
  }
  const bool is3dNoRot = allZero({1, 2, 4, 6, 8, 9}) && bottomRow;
  if (is3dNoRot) {
    if (sq(m[0] - m[5]) < sq(1e-6f) && sq(m[0] - m[10]) < sq(1e-6f)) {
      if (sq(m[0] - 1.0f) > sq(1e-6f)) f.uniformScale = true;
    } else {
      f.generalScale = true;
    }
    return MatrixType::k3dNoRot;
  }
  if (bottomRow) {
    const float c1 = (m[0] * m[0] + m[1] * m[1]) + m[2] * m[2];
    const float c2 = (m[4] * m[4] + m[5] * m[5]) + m[6] * m[6];
    const float c3 = (m[8] * m[8] + m[9] * m[9]) + m[10] * m[10];
    const float d1 = (m[0] * m[4] + m[1] * m[5]) + m[2] * m[6];
    if (sq(c1 - c2) < sq(1e-6f) && sq(c1 - c3) < sq(1e-6f)) {
      if (sq(c1 - 1.0f) > sq(1e-6f)) f.uniformScale = true;
    } else {
      f.generalScale = true;
    }
    if (sq(d1) < sq(1e-6f)) {
      float cp[3] = {m[1] * m[6] - m[2] * m[5], m[2] * m[4] - m[0] * m[6], m[0] * m[5] - m[1] * m[4]};
      cp[0] -= m[8];
      cp[1] -= m[9];
      cp[2] -= m[10];
      if ((cp[0] * cp[0] + cp[1] * cp[1]) + cp[2] * cp[2] < sq(1e-6f))
        f.rotation = true;
      else
        f.general3d = true;
    } else {
      f.general3d = true;
    }
    return MatrixType::k3d;
  }
  const bool perspective = allZero({1, 2, 3, 4, 6, 7, 12, 13, 15}) && m[11] == -1.0f;
  f.general = true;
  return perspective ? MatrixType::kPerspective : MatrixType::kGeneral;
}

// Gauss-Jordan elimination with partial pivoting, in the order of Mesa's
// util_invert_mat4x4 (rows of [M | I], pivots chosen by |value|, strictly).
bool invertGeneral(const glm::mat4& in, glm::mat4& out) {
  float rows[4][8];
  float* r[4] = {rows[0], rows[1], rows[2], rows[3]};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) r[i][j] = at(in, i, j);
    for (int j = 4; j < 8; ++j) r[i][j] = (j - 4 == i) ? 1.0f : 0.0f;
  }
  // First column.
  if (std::fabs(r[3][0]) > std::fabs(r[2][0])) std::swap(r[3], r[2]);
  if (std::fabs(r[2][0]) > std::fabs(r[1][0])) std::swap(r[2], r[1]);
  if (std::fabs(r[1][0]) > std::fabs(r[0][0])) std::swap(r[1], r[0]);
  if (r[0][0] == 0.0f) return false;
  {
    const float m1 = r[1][0] / r[0][0], m2 = r[2][0] / r[0][0], m3 = r[3][0] / r[0][0];
    for (int c = 1; c < 8; ++c) {
      const float s = r[0][c];
      if (c >= 4 && s == 0.0f) continue;
      r[1][c] -= m1 * s;
      r[2][c] -= m2 * s;
      r[3][c] -= m3 * s;
    }
  }
  // Second column.
  if (std::fabs(r[3][1]) > std::fabs(r[2][1])) std::swap(r[3], r[2]);
  if (std::fabs(r[2][1]) > std::fabs(r[1][1])) std::swap(r[2], r[1]);
  if (r[1][1] == 0.0f) return false;
  {
    const float m2 = r[2][1] / r[1][1], m3 = r[3][1] / r[1][1];
    for (int c = 2; c < 8; ++c) {
      const float s = r[1][c];
      if (c >= 4 && s == 0.0f) continue;
      r[2][c] -= m2 * s;
      r[3][c] -= m3 * s;
    }
  }
  // Third column.
  if (std::fabs(r[3][2]) > std::fabs(r[2][2])) std::swap(r[3], r[2]);
  if (r[2][2] == 0.0f) return false;
  {
    const float m3 = r[3][2] / r[2][2];
    for (int c = 3; c < 8; ++c) r[3][c] -= m3 * r[2][c];
  }
  if (r[3][3] == 0.0f) return false;
  // Back substitution.
  float s = 1.0f / r[3][3];
  for (int c = 4; c < 8; ++c) r[3][c] *= s;
  float m2 = r[2][3];
  s = 1.0f / r[2][2];
  for (int c = 4; c < 8; ++c) r[2][c] = s * (r[2][c] - r[3][c] * m2);
  float m1 = r[1][3];
  for (int c = 4; c < 8; ++c) r[1][c] -= r[3][c] * m1;
  float m0 = r[0][3];
  for (int c = 4; c < 8; ++c) r[0][c] -= r[3][c] * m0;
  m1 = r[1][2];
  s = 1.0f / r[1][1];
  for (int c = 4; c < 8; ++c) r[1][c] = s * (r[1][c] - r[2][c] * m1);
  m0 = r[0][2];
  for (int c = 4; c < 8; ++c) r[0][c] -= r[2][c] * m0;
  m0 = r[0][1];
  s = 1.0f / r[0][0];
  for (int c = 4; c < 8; ++c) r[0][c] = s * (r[0][c] - r[1][c] * m0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) at(out, i, j) = r[i][4 + j];
  return true;
}

// The translation column of an affine inverse: -(R^-1 t), summed left to right.
void invertTranslation(const glm::mat4& in, glm::mat4& out) {
  for (int i = 0; i < 3; ++i)
    at(out, i, 3) =
        -((at(in, 0, 3) * at(out, i, 0) + at(in, 1, 3) * at(out, i, 1)) + at(in, 2, 3) * at(out, i, 2));
}

// invert_matrix_3d_general: cofactors over a determinant whose positive and
// negative terms are summed apart.
bool invert3dGeneral(const glm::mat4& in, glm::mat4& out) {
  float pos = 0, neg = 0;
  auto add = [&](float t) {
    if (t >= 0.0f)
      pos += t;
    else
      neg += t;
  };
  add(at(in, 0, 0) * at(in, 1, 1) * at(in, 2, 2));
  add(at(in, 1, 0) * at(in, 2, 1) * at(in, 0, 2));
  add(at(in, 2, 0) * at(in, 0, 1) * at(in, 1, 2));
  add(-at(in, 2, 0) * at(in, 1, 1) * at(in, 0, 2));
  add(-at(in, 1, 0) * at(in, 0, 1) * at(in, 2, 2));
  add(-at(in, 0, 0) * at(in, 2, 1) * at(in, 1, 2));
  float det = pos + neg;
  if (std::fabs(det) < 1e-25f) return false;
  det = 1.0f / det;
  out = glm::mat4(1.0f);
  at(out, 0, 0) = ((at(in, 1, 1) * at(in, 2, 2) - at(in, 2, 1) * at(in, 1, 2)) * det);
  at(out, 0, 1) = (-(at(in, 0, 1) * at(in, 2, 2) - at(in, 2, 1) * at(in, 0, 2)) * det);
  at(out, 0, 2) = ((at(in, 0, 1) * at(in, 1, 2) - at(in, 1, 1) * at(in, 0, 2)) * det);
  at(out, 1, 0) = (-(at(in, 1, 0) * at(in, 2, 2) - at(in, 2, 0) * at(in, 1, 2)) * det);
  at(out, 1, 1) = ((at(in, 0, 0) * at(in, 2, 2) - at(in, 2, 0) * at(in, 0, 2)) * det);
  at(out, 1, 2) = (-(at(in, 0, 0) * at(in, 1, 2) - at(in, 1, 0) * at(in, 0, 2)) * det);
  at(out, 2, 0) = ((at(in, 1, 0) * at(in, 2, 1) - at(in, 2, 0) * at(in, 1, 1)) * det);
  at(out, 2, 1) = (-(at(in, 0, 0) * at(in, 2, 1) - at(in, 2, 0) * at(in, 0, 1)) * det);
  at(out, 2, 2) = ((at(in, 0, 0) * at(in, 1, 1) - at(in, 1, 0) * at(in, 0, 1)) * det);
  invertTranslation(in, out);
  return true;
}

// invert_matrix_3d: a (scaled) transpose for angle-preserving matrices.
bool invert3d(const glm::mat4& in, const Flags& f, glm::mat4& out) {
  const bool anglePreserving = !f.general && !f.generalScale && !f.general3d;
  if (!anglePreserving) return invert3dGeneral(in, out);
  out = glm::mat4(1.0f);
  if (f.uniformScale) {
    float scale = (at(in, 0, 0) * at(in, 0, 0) + at(in, 0, 1) * at(in, 0, 1)) + at(in, 0, 2) * at(in, 0, 2);
    if (scale == 0.0f) return false;
    scale = 1.0f / scale;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) at(out, i, j) = scale * at(in, j, i);
  } else if (f.rotation) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) at(out, i, j) = at(in, j, i);
  } else {  // pure translation
    for (int i = 0; i < 3; ++i) at(out, i, 3) = -at(in, i, 3);
    return true;
  }
  if (f.translation) invertTranslation(in, out);
  return true;
}

bool invertNoRot(const glm::mat4& in, const Flags& f, int dims, glm::mat4& out) {
  for (int i = 0; i < dims; ++i)
    if (at(in, i, i) == 0.0f) return false;
  out = glm::mat4(1.0f);
  for (int i = 0; i < dims; ++i) at(out, i, i) = 1.0f / at(in, i, i);
  if (f.translation)
    for (int i = 0; i < dims; ++i) at(out, i, 3) = -(at(in, i, 3) * at(out, i, i));
  return true;
}

}  // namespace

ModelviewAnalysis analyseModelview(const glm::mat4& m) {
  ModelviewAnalysis a;
  Flags f;
  const MatrixType type = classify(m, f);
  bool ok = true;
  switch (type) {
    case MatrixType::kIdentity: a.inverse = glm::mat4(1.0f); break;
    case MatrixType::k3dNoRot: ok = invertNoRot(m, f, 3, a.inverse); break;
    case MatrixType::k2dNoRot: ok = invertNoRot(m, f, 2, a.inverse); break;
    case MatrixType::k2d:
    case MatrixType::k3d: ok = invert3d(m, f, a.inverse); break;
    case MatrixType::kPerspective:
    case MatrixType::kGeneral: ok = invertGeneral(m, a.inverse); break;
  }
  if (!ok) a.inverse = glm::mat4(1.0f);
  a.invertible = ok;
  a.lengthPreserving = !f.general && !f.generalScale && !f.uniformScale && !f.general3d && ok;
  a.normalRescale = 1.0f;
  if (!a.lengthPreserving) {
    // update_modelview_scale: inv[2], inv[6], inv[10] (the inverse's third row).
    const float* inv = &a.inverse[0][0];
    float f2 = (inv[2] * inv[2] + inv[6] * inv[6]) + inv[10] * inv[10];
    if (f2 < 1e-12f) f2 = 1.0f;
    a.normalRescale = 1.0f / std::sqrt(f2);
  }
  return a;
}

glm::vec4 transformPointLikeMesa(const glm::mat4& m, const glm::vec4& p) {
  glm::vec4 q;
  for (int i = 0; i < 4; ++i) q[i] = ((m[0][i] * p[0] + m[1][i] * p[1]) + m[2][i] * p[2]) + m[3][i] * p[3];
  return q;
}

glm::vec3 transformDirectionLikeMesa(const glm::mat4& m, const glm::vec3& d) {
  glm::vec3 q;
  for (int i = 0; i < 3; ++i) q[i] = (d[0] * m[0][i] + d[1] * m[1][i]) + d[2] * m[2][i];
  return q;
}

glm::vec3 transformNormalLikeMesa(const glm::mat4& m, const glm::vec3& n) {
  glm::vec3 q;
  for (int i = 0; i < 3; ++i) q[i] = (n[0] * m[i][0] + n[1] * m[i][1]) + n[2] * m[i][2];
  return q;
}

}  // namespace glfixed::vertex
