// Fog's per-draw state (GL 2.1 §3.10), as the fragment stage reads it
// (ShadeTarget::fog; the code is fragment/fog.inc). The constants are Mesa's
// STATE_FOG_PARAMS_OPTIMIZED (prog_statevars.c), which the fixed-function
// fragment shader reads.
#pragma once

#include <GL/gl.h>

#include <glm/glm.hpp>

namespace glfixed::fragment {

struct FogState {
  enum class Mode { kNone, kLinear, kExp, kExp2 };
  Mode mode = Mode::kNone;  // kNone: fog is off (and the vertices carry no fog distance)
  // Linear: f = c * scale + offset, scale = -1 / (end - start) (1 when end ==
  // start), offset = end * -scale, in single precision.
  float scale = 1, offset = 0;
  // GL_EXP: f = 2^-(c * density), density = d / ln 2; GL_EXP2:
  // f = 2^-((c * density)^2), density = d / sqrt(ln 2); each the double
  // product rounded to float once.
  float density = 0;
  float color[3] = {0, 0, 0};  // the fog colour clamped to [0, 1] (8-bit buffers)
  bool active() const { return mode != Mode::kNone; }
};

FogState makeFogState(bool enabled, GLenum mode, float density, float start, float end,
                      const glm::vec4& color);

}  // namespace glfixed::fragment
