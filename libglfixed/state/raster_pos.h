// The current raster position (GL 2.1 §2.13). GL puts it in the
// GL_CURRENT_BIT attribute group.
#pragma once

#include <glm/glm.hpp>

namespace glfixed {

struct RasterPosState {
  glm::vec4 position{0, 0, 0, 1};  // window x, y (GL's, up), z; clip w
  bool valid = true;
  float distance = 0;  // eye distance
  glm::vec4 color{1, 1, 1, 1};
  glm::vec4 secondaryColor{0, 0, 0, 1};
  glm::vec4 texCoord{0, 0, 0, 1};
};

}  // namespace glfixed
