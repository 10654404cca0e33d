// libglfixed's side of the evaluator comparison: the cases of eval_cases.h
// evaluated by pipeline::evaluate1/evaluate2, printed as mesa_eval_feedback
// prints Mesa's feedback (the evaluated x, the colour, the texture coordinates).
#include <cstdio>

#include "eval_cases.h"
#include "pipeline/evaluator.h"

using namespace glfixed;

namespace {

void setMap(EvalMap& m, const eval_case& c, const float* points, int k) {
  m.uorder = c.uorder;
  m.vorder = c.vorder;
  m.u1 = c.u1;
  m.u2 = c.u2;
  m.v1 = c.two_d ? c.v1 : 0.0f;
  m.v2 = c.two_d ? c.v2 : 1.0f;
  m.points.assign(points, points + c.uorder * c.vorder * k);
}

}  // namespace

int main() {
  static eval_case c;
  static float rotated[30 * 30 * 3];
  for (int n = 0; n < EVAL_CASES; ++n) {
    eval_make_case(n, &c);
    for (int k = 0; k < EVAL_ROTATIONS; ++k) {
      eval_rotate_vertices(&c, k, rotated);
      EvalAttrib state;
      EvalMaps maps;
      auto& enabled = c.two_d ? state.map2Enabled : state.map1Enabled;
      auto& table = c.two_d ? maps.map2 : maps.map1;
      for (GLenum target : {GL_MAP1_VERTEX_3, GL_MAP1_COLOR_4, GL_MAP1_TEXTURE_COORD_4}) {
        const int slot = evalSlot(target);
        enabled[slot] = true;
        const float* points = target == GL_MAP1_VERTEX_3  ? rotated
                              : target == GL_MAP1_COLOR_4 ? c.color
                                                          : c.tex;
        setMap(table[slot], c, points, evalComponents(target));
      }
      state.autoNormal = c.auto_normal != 0;
      for (int i = 0; i < EVAL_COORDS; ++i) {
        const pipeline::EvaluatedVertex e = c.two_d ? pipeline::evaluate2(state, maps, c.u[i], c.v[i])
                                                    : pipeline::evaluate1(state, maps, c.u[i]);
        std::printf("%d %d %a  %a %a %a %a  %a %a %a %a\n", n, k, e.position.x, e.color.r, e.color.g,
                    e.color.b, e.color.a, e.texCoord.s, e.texCoord.t, e.texCoord.p, e.texCoord.q);
      }
    }
  }
  return 0;
}
