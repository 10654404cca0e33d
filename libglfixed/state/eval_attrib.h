// Evaluator state (GL 2.1 §5.1, table 6.39). GL_EVAL_BIT pushes the map
// enables, GL_AUTO_NORMAL and the two grids (EvalAttrib); the maps themselves
// (order, domain, control points) belong to no attribute group (EvalMaps).
#pragma once

#include <GL/gl.h>

#include <array>
#include <vector>

namespace glfixed {

constexpr int kMaxEvalOrder = 30;  // GL_MAX_EVAL_ORDER, as Mesa
// The nine targets of each dimension, in enum order: COLOR_4, INDEX, NORMAL,
// TEXTURE_COORD_1..4, VERTEX_3, VERTEX_4 (GL_MAP1_COLOR_4 + i, GL_MAP2_COLOR_4 + i).
constexpr int kEvalTargets = 9;

// Table 5.1: values per control point; 0 for a name that is not a map.
inline int evalComponents(GLenum target) {
  static constexpr int k[kEvalTargets] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
  if (target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4) return k[target - GL_MAP1_COLOR_4];
  if (target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4) return k[target - GL_MAP2_COLOR_4];
  return 0;
}
// The slot 0..8 of a GL_MAP1_* or GL_MAP2_* name; -1 for another name.
inline int evalSlot(GLenum target) {
  if (target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4) return int(target - GL_MAP1_COLOR_4);
  if (target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4) return int(target - GL_MAP2_COLOR_4);
  return -1;
}
inline bool isMap1Target(GLenum t) { return t >= GL_MAP1_COLOR_4 && t <= GL_MAP1_VERTEX_4; }
inline bool isMap2Target(GLenum t) { return t >= GL_MAP2_COLOR_4 && t <= GL_MAP2_VERTEX_4; }

// GL_EVAL_BIT.
struct EvalAttrib {
  std::array<bool, kEvalTargets> map1Enabled{};  // by evalSlot
  std::array<bool, kEvalTargets> map2Enabled{};
  bool autoNormal = false;
  // glMapGrid1 / glMapGrid2, stored as the floats Mesa stores.
  int grid1Segments = 1;
  float grid1U1 = 0, grid1U2 = 1;
  int grid2USegments = 1, grid2VSegments = 1;
  float grid2U1 = 0, grid2U2 = 1, grid2V1 = 0, grid2V2 = 1;

  // The flag glEnable/glDisable/glIsEnabled reach for `cap`; null if `cap`
  // is not an evaluator capability.
  bool* capability(GLenum cap) {
    if (cap == GL_AUTO_NORMAL) return &autoNormal;
    if (isMap1Target(cap)) return &map1Enabled[evalSlot(cap)];
    if (isMap2Target(cap)) return &map2Enabled[evalSlot(cap)];
    return nullptr;
  }
};

// One map: the control points tightly packed, k values each; a 2D map's
// points run over v fastest (point (i, j) at (i * vorder + j) * k), the order
// glGetMap(GL_COEFF) returns them in.
struct EvalMap {
  int uorder = 1, vorder = 1;  // vorder is 1 for a 1D map
  float u1 = 0, u2 = 1, v1 = 0, v2 = 1;
  std::vector<float> points;
};

// The initial maps of table 6.39: order 1, domain [0,1], one control point
// holding the initial value of the attribute.
struct EvalMaps {
  std::array<EvalMap, kEvalTargets> map1, map2;
  EvalMaps() {
    static const float initial[kEvalTargets][4] = {{1, 1, 1, 1}, {1, 0, 0, 0}, {0, 0, 1, 0},
                                                   {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0},
                                                   {0, 0, 0, 1}, {0, 0, 0, 0}, {0, 0, 0, 1}};
    for (int i = 0; i < kEvalTargets; ++i) {
      const int k = evalComponents(GL_MAP1_COLOR_4 + i);
      map1[i].points.assign(initial[i], initial[i] + k);
      map2[i].points.assign(initial[i], initial[i] + k);
    }
  }
  EvalMap* find(GLenum target) {
    if (isMap1Target(target)) return &map1[evalSlot(target)];
    if (isMap2Target(target)) return &map2[evalSlot(target)];
    return nullptr;
  }
};

}  // namespace glfixed
