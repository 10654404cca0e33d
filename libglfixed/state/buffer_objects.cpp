#include "state/buffer_objects.h"

namespace glfixed {

void BufferObjects::generate(GLsizei n, GLuint* names) {
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (objects_.count(next) || reserved_.count(next)) ++next;
    reserved_.insert(next);
    names[i] = next;
  }
}

BufferObject* BufferObjects::bind(GLuint name) {
  if (name == 0) return nullptr;
  auto it = objects_.find(name);
  if (it != objects_.end()) return it->second.get();
  reserved_.erase(name);
  return (objects_[name] = std::make_unique<BufferObject>()).get();
}

BufferObject* BufferObjects::find(GLuint name) {
  auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : it->second.get();
}

const BufferObject* BufferObjects::find(GLuint name) const {
  auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : it->second.get();
}

void BufferObjects::remove(GLuint name) {
  objects_.erase(name);
  reserved_.erase(name);
}

}  // namespace glfixed
