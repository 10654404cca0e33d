// GL_TEXTURE_BIT, per unit: the names of the texture objects bound to each
// target (table 6.25, TEXTURE_BINDING_xD). The objects themselves live in the
// context's shared texture namespace (texture/texture_object.h).
#pragma once

#include <GL/gl.h>

namespace glfixed {

struct TextureBindings {
  GLuint texture1D = 0, texture2D = 0, texture3D = 0, textureCubeMap = 0;
};

}  // namespace glfixed
