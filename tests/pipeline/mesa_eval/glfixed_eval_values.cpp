// libglfixed's side of the evaluator comparison: the cases of eval_cases.h
// evaluated by pipeline::evaluate1/evaluate2, printed as mesa_eval_feedback
// prints Mesa's feedback (the evaluated x, the colour, the texture coordinates).
#include <cmath>
#include <cstdio>

#include "api/eval_commands.h"
#include "eval_cases.h"
#include "pipeline/evaluator.h"
#include "state/context.h"

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
  // The grids, through the commands themselves on a context of our own
  // (no framebuffer: nothing is drawn); consecutive GL_POINTS stay pending
  // as one draw, so the vertices are all there in ctx.pending afterwards.
  for (int n = 0; n < EVAL_GRIDS; ++n) {
    eval_grid g;
    eval_make_case(n, &c);
    eval_make_grid(n, &g);
    for (int k = 0; k < EVAL_ROTATIONS; ++k) {
      Context ctx(24);
      setCurrentContext(&ctx);
      eval_rotate_vertices(&c, k, rotated);
      const int count = c.uorder * c.vorder * 3;
      if (c.two_d) {
        api::map2(GL_MAP2_VERTEX_3, c.u1, c.u2, 3 * c.vorder, c.uorder, c.v1, c.v2, 3, c.vorder,
                  std::vector<float>(rotated, rotated + count));
        *ctx.eval.capability(GL_MAP2_VERTEX_3) = true;
        api::mapGrid2(g.n, g.gu1, g.gu2, g.m, g.gv1, g.gv2);
        api::evalMesh2(GL_POINT, g.i1, g.i2, g.j1, g.j2);
      } else {
        api::map1(GL_MAP1_VERTEX_3, c.u1, c.u2, 3, c.uorder, std::vector<float>(rotated, rotated + count));
        *ctx.eval.capability(GL_MAP1_VERTEX_3) = true;
        api::mapGrid1(g.n, g.gu1, g.gu2);
        api::evalMesh1(GL_POINT, g.i1, g.i2);
      }
      glBegin(GL_POINTS);
      for (int i = 0; i < 8; ++i) {
        if (c.two_d)
          api::evalPoint2(g.points[i][0], g.points[i][1]);
        else
          api::evalPoint1(g.points[i][0]);
      }
      glEnd();
      // Feedback returns only the points inside the view volume.
      for (const glm::vec4& p : ctx.pending.position)
        if (std::fabs(p.x) <= p.w && std::fabs(p.y) <= p.w && std::fabs(p.z) <= p.w)
          std::printf("grid %d %d %a\n", n, k, p.x);
      setCurrentContext(nullptr);
    }
  }
  return 0;
}
