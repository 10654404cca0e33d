// GL_TEXTURE_BIT, per unit: texture coordinate generation (GL 2.1 §2.11.4,
// table 6.26), one entry per coordinate s, t, r, q. The enables are in
// TextureUnitEnables (they belong to GL_ENABLE_BIT too).
#pragma once

#include <GL/gl.h>

#include <array>
#include <glm/glm.hpp>

namespace glfixed {

struct TexGenAttrib {
  struct Coord {
    GLenum mode = GL_EYE_LINEAR;
    glm::vec4 objectPlane{0, 0, 0, 0};
    glm::vec4 eyePlane{0, 0, 0, 0};
  };
  // s: (1, 0, 0, 0), t: (0, 1, 0, 0), r and q: 0 (table 6.26).
  std::array<Coord, 4> coord = {Coord{GL_EYE_LINEAR, {1, 0, 0, 0}, {1, 0, 0, 0}},
                                Coord{GL_EYE_LINEAR, {0, 1, 0, 0}, {0, 1, 0, 0}}, Coord{}, Coord{}};
};

}  // namespace glfixed
