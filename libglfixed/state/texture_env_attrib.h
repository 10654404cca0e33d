// GL_TEXTURE_BIT, per unit: the texture environment (GL 2.1 §3.8.13, table
// 6.27) and the unit's level-of-detail bias (§3.8.8, TEXTURE_LOD_BIAS of
// glTexEnv's GL_TEXTURE_FILTER_CONTROL).
#pragma once

#include <GL/gl.h>

#include <array>
#include <glm/glm.hpp>

namespace glfixed {

struct TexEnvAttrib {
  GLenum mode = GL_MODULATE;
  glm::vec4 color{0, 0, 0, 0};  // GL_TEXTURE_ENV_COLOR, clamped to [0,1] when set
  float lodBias = 0;
  // GL_COMBINE's state (table 6.27, initial values of §3.8.13).
  GLenum combineRGB = GL_MODULATE, combineAlpha = GL_MODULATE;
  std::array<GLenum, 3> sourceRGB{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> sourceAlpha{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> operandRGB{GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  std::array<GLenum, 3> operandAlpha{GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgbScale = 1, alphaScale = 1;  // 1, 2 or 4
};

}  // namespace glfixed
