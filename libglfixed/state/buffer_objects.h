// Buffer objects (GL 2.1 §2.9): the names and data stores of one context
// (later shared between contexts of a share group). A name from glGenBuffers
// becomes an object when it is first bound.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace glfixed {

struct BufferObject {
  std::vector<uint8_t> data;  // the data store; its size is GL_BUFFER_SIZE
  GLenum usage = GL_STATIC_DRAW;
  GLenum access = GL_READ_WRITE;
  bool mapped = false;
  void* mapPointer = nullptr;  // GL_BUFFER_MAP_POINTER
  GLsizeiptr size() const { return static_cast<GLsizeiptr>(data.size()); }
};

class BufferObjects {
 public:
  // Names not in use, none of them 0 (glGenBuffers).
  void generate(GLsizei n, GLuint* names);
  // The object of `name`, created if the name is new (glBindBuffer); null for 0.
  BufferObject* bind(GLuint name);
  // The object, or null if `name` names none.
  BufferObject* find(GLuint name);
  const BufferObject* find(GLuint name) const;
  // Frees the name and the data store (glDeleteBuffers).
  void remove(GLuint name);

 private:
  std::map<GLuint, std::unique_ptr<BufferObject>> objects_;
  std::set<GLuint> reserved_;  // generated, not bound yet
};

}  // namespace glfixed
