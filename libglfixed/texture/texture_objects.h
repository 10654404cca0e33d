// The texture object name space (GL 2.1 §3.8.12): the objects named by
// glGenTextures/glBindTexture, and the default texture of each target
// (name 0). Contexts that share display lists share it (Mesa keeps both the
// named and the default textures in its shared state).
#pragma once

#include <GL/gl.h>

#include <map>
#include <memory>
#include <set>

#include "state/texture_binding_attrib.h"
#include "texture/texture_object.h"

namespace glfixed::texture {

// The four targets a texture object can have; -1 for any other enum.
int targetIndex(GLenum target);
constexpr int kTargetCount = 4;  // 1D, 2D, 3D, cube map

class TextureObjects {
 public:
  TextureObjects();
  // Names not in use, none of them 0 (glGenTextures).
  void generate(GLsizei n, GLuint* names);
  // The object of `name`, created (without a target) if the name is new
  // (glBindTexture: any unused name may be bound, GL 2.1 §3.8.12).
  TextureObject* obtain(GLuint name);
  // The object, or null if `name` names none (0 names none).
  TextureObject* find(GLuint name);
  const TextureObject* find(GLuint name) const;
  // The default texture of a target index (targetIndex).
  TextureObject& defaultTexture(int index) { return *defaults_[index]; }
  const TextureObject& defaultTexture(int index) const { return *defaults_[index]; }
  // Frees the name and the images (glDeleteTextures).
  void remove(GLuint name);
  // The proxy texture of a target index (GL_PROXY_TEXTURE_xD, §3.8.11):
  // images without texels, only their sizes and formats.
  TextureObject& proxy(int index) { return *proxies_[index]; }

 private:
  std::map<GLuint, std::unique_ptr<TextureObject>> objects_;
  std::set<GLuint> reserved_;  // generated, not bound yet
  std::unique_ptr<TextureObject> defaults_[kTargetCount];
  std::unique_ptr<TextureObject> proxies_[kTargetCount];
};

// The binding of a target index in one unit's bindings.
GLuint& bindingOf(TextureBindings& bindings, int index);
GLuint bindingOf(const TextureBindings& bindings, int index);

// The object a unit samples or the texture commands address for a target
// index: the bound object, or the target's default texture for name 0.
TextureObject& boundObject(TextureObjects& objects, const TextureBindings& bindings, int index);
const TextureObject& boundObject(const TextureObjects& objects, const TextureBindings& bindings, int index);

}  // namespace glfixed::texture
