// The evaluator commands (GL 2.1 §5.1) as plain C++ functions taking their
// arguments by value, so that a display list can record a call and replay it
// through the same function: glMap's control points are gathered from client
// memory first (gatherMapPoints), and the command checks every argument
// itself when it runs. Each acts on the current context.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <vector>

#include "state/eval_attrib.h"

namespace glfixed {
class Context;
}

namespace glfixed::api {

// The control points a glMap1 (vorder 1, vstride 0) or glMap2 call reads,
// packed as EvalMap keeps them, doubles rounded to float. Empty when the call
// will fail anyway (null points, a bad target, order or stride), so that
// nothing is read outside what the caller passed.
template <typename T>
std::vector<float> gatherMapPoints(GLenum target, GLint ustride, GLint uorder, GLint vstride, GLint vorder,
                                   const T* points) {
  const int k = evalComponents(target);
  if (!points || k == 0 || uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 || vorder > kMaxEvalOrder ||
      ustride < k || (vorder > 1 && vstride < k))
    return {};
  std::vector<float> packed;
  packed.reserve(size_t(uorder) * vorder * k);
  for (int i = 0; i < uorder; ++i)
    for (int j = 0; j < vorder; ++j)
      for (int c = 0; c < k; ++c)
        packed.push_back(static_cast<float>(points[ptrdiff_t(i) * ustride + ptrdiff_t(j) * vstride + c]));
  return packed;
}

// glMap1 / glMap2 with the points gathered; an empty `points` stands for a
// null pointer.
void map1(GLenum target, float u1, float u2, GLint stride, GLint order, std::vector<float> points);
void map2(GLenum target, float u1, float u2, GLint ustride, GLint uorder, float v1, float v2, GLint vstride,
          GLint vorder, std::vector<float> points);
void mapGrid1(GLint un, float u1, float u2);
void mapGrid2(GLint un, float u1, float u2, GLint vn, float v1, float v2);
void evalCoord1(float u);
void evalCoord2(float u, float v);
void evalPoint1(GLint i);
void evalPoint2(GLint i, GLint j);
void evalMesh1(GLenum mode, GLint i1, GLint i2);
void evalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2);

// glGet of the evaluator state (table 6.39); false for another pname.
bool getEvalState(const Context& ctx, GLenum pname, GLdouble* out, int* count);

}  // namespace glfixed::api
