// GL_TEXTURE_BIT, per unit: the texture environment (GL 2.1 §3.8.13, table
// 6.27) and the unit's level-of-detail bias (§3.8.8, TEXTURE_LOD_BIAS of
// glTexEnv's GL_TEXTURE_FILTER_CONTROL).
#pragma once

#include <GL/gl.h>

#include <glm/glm.hpp>

namespace glfixed {

struct TexEnvAttrib {
  GLenum mode = GL_MODULATE;
  glm::vec4 color{0, 0, 0, 0};
  float lodBias = 0;
};

}  // namespace glfixed
