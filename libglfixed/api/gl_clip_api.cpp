// User clip planes (GL 2.1 §2.12): glClipPlane and glGetClipPlane. The plane
// is stored in eye space as Mesa stores it (main/clip.c): the doubles become
// floats, then the row vector is multiplied by Mesa's float inverse of the
// modelview at the time of the call (vertex/lighting_matrix.h,
// primitive::transformPlane). The draw maps it on to clip space
// (pipeline/draw.cpp).
// Every float operation here must round as Mesa's C does: no fused
// multiply-adds.
#pragma GCC optimize("fp-contract=off")

#include "api/api.h"
#include "api/list_record.h"
#include "primitive/clip.h"
#include "vertex/lighting_matrix.h"

using namespace glfixed;

namespace {

// GL_CLIP_PLANEi -> i, or -1: not a clip plane (GL_INVALID_ENUM).
int planeIndex(GLenum plane) {
  const long i = static_cast<long>(plane) - static_cast<long>(GL_CLIP_PLANE0);
  return (i >= 0 && i < kMaxClipPlanes) ? static_cast<int>(i) : -1;
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glClipPlane(GLenum plane, const GLdouble* equation) {
  if (api::compiled(&glClipPlane, plane, api::copied(equation, 4))) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const int p = planeIndex(plane);
  if (p < 0) return ctx->recordError(GL_INVALID_ENUM);
  if (!equation) return;  // no plane to read; GL gives no error for it
  const glm::vec4 objectPlane(static_cast<float>(equation[0]), static_cast<float>(equation[1]),
                              static_cast<float>(equation[2]), static_cast<float>(equation[3]));
  const glm::mat4 objectFromEye = vertex::analyseModelview(ctx->modelview.top()).inverse;
  const glm::vec4 eyePlane = primitive::transformPlane(objectPlane, objectFromEye);
  // Compared bit for bit as Mesa's TEST_EQ_4V does (a NaN plane is never equal).
  api::setState(*ctx, ctx->transform.clipPlane[p], eyePlane, GL_TRANSFORM_BIT);
}

GLAPI void APIENTRY glGetClipPlane(GLenum plane, GLdouble* equation) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  const int p = planeIndex(plane);
  if (p < 0) return ctx->recordError(GL_INVALID_ENUM);
  if (!equation) return;
  for (int i = 0; i < 4; ++i) equation[i] = ctx->transform.clipPlane[p][i];
}

}  // extern "C"
