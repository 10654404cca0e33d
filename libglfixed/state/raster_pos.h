// The current raster position (GL 2.1 §2.13). GL puts it in the
// GL_CURRENT_BIT attribute group.
#pragma once

#include <array>
#include <glm/glm.hpp>

namespace glfixed {

struct RasterPosState {
  glm::vec4 position{0, 0, 0, 1};  // window x, y (GL's, up), z; clip w
  bool valid = true;
  float distance = 0;  // eye distance
  glm::vec4 color{1, 1, 1, 1};
  glm::vec4 secondaryColor{0, 0, 0, 1};
  glm::vec4 texCoord{0, 0, 0, 1};  // unit 0's (feedback reports it)
  // Texture coordinates (issue 14): every unit's, after texgen and the
  // texture matrix; GL_CURRENT_RASTER_TEXTURE_COORDS is the active unit's.
  std::array<glm::vec4, 8> unitTexCoord{{{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1},
                                         {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}}};
};

}  // namespace glfixed
