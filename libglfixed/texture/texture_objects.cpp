#include "texture/texture_objects.h"

#include <algorithm>

namespace glfixed::texture {

int targetIndex(GLenum target) {
  switch (target) {
    case GL_TEXTURE_1D: return 0;
    case GL_TEXTURE_2D: return 1;
    case GL_TEXTURE_3D: return 2;
    case GL_TEXTURE_CUBE_MAP: return 3;
    default: return -1;
  }
}

TextureObjects::TextureObjects() {
  const GLenum targets[kTargetCount] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP};
  for (int i = 0; i < kTargetCount; ++i) {
    defaults_[i] = std::make_unique<TextureObject>();
    defaults_[i]->target = targets[i];
    proxies_[i] = std::make_unique<TextureObject>();
    proxies_[i]->target = targets[i];
  }
}

void TextureObjects::generate(GLsizei n, GLuint* names) {
  // As Mesa's hash table without name reuse: past the highest name in use.
  GLuint next = 1;
  if (!objects_.empty()) next = std::max(next, objects_.rbegin()->first + 1);
  if (!reserved_.empty()) next = std::max(next, *reserved_.rbegin() + 1);
  for (GLsizei i = 0; i < n; ++i) {
    while (objects_.count(next) || reserved_.count(next)) ++next;
    reserved_.insert(next);
    names[i] = next++;
  }
}

TextureObject* TextureObjects::obtain(GLuint name) {
  if (name == 0) return nullptr;
  auto it = objects_.find(name);
  if (it != objects_.end()) return it->second.get();
  reserved_.erase(name);
  auto object = std::make_unique<TextureObject>();
  object->name = name;
  TextureObject* raw = object.get();
  objects_.emplace(name, std::move(object));
  return raw;
}

TextureObject* TextureObjects::find(GLuint name) {
  auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : it->second.get();
}

const TextureObject* TextureObjects::find(GLuint name) const {
  auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : it->second.get();
}

void TextureObjects::remove(GLuint name) {
  objects_.erase(name);
  reserved_.erase(name);
}

GLuint& bindingOf(TextureBindings& b, int index) {
  switch (index) {
    case 0: return b.texture1D;
    case 1: return b.texture2D;
    case 2: return b.texture3D;
    default: return b.textureCubeMap;
  }
}
GLuint bindingOf(const TextureBindings& b, int index) {
  return bindingOf(const_cast<TextureBindings&>(b), index);
}

TextureObject& boundObject(TextureObjects& objects, const TextureBindings& bindings, int index) {
  TextureObject* object = objects.find(bindingOf(bindings, index));
  return object ? *object : objects.defaultTexture(index);
}
const TextureObject& boundObject(const TextureObjects& objects, const TextureBindings& bindings, int index) {
  const TextureObject* object = objects.find(bindingOf(bindings, index));
  return object ? *object : objects.defaultTexture(index);
}

}  // namespace glfixed::texture
