// Buffer objects (GL 2.1 §2.9): the names and data stores of one context
// (later shared between contexts of a share group). A name from glGenBuffers
// becomes an object when it is first bound.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <utility>
#include <vector>

namespace glfixed {

// The data store's allocator. calloc, not operator new: a store too large to
// allocate fails with null, which glBufferData turns into GL_OUT_OF_MEMORY,
// where a sanitizer's operator new ends the program; and a large store's
// zeroed pages are not touched until written (Mesa's are not either).
template <typename T>
struct StoreAllocator {
  using value_type = T;
  StoreAllocator() = default;
  template <typename U>
  StoreAllocator(const StoreAllocator<U>&) {}
  T* allocate(size_t n) {
    void* p = std::calloc(n, sizeof(T));
    if (!p) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t) { std::free(p); }
  // A new element is left as calloc made it (zero), not written again.
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const StoreAllocator<U>&) const {
    return true;
  }
  template <typename U>
  bool operator!=(const StoreAllocator<U>&) const {
    return false;
  }
};
using DataStore = std::vector<uint8_t, StoreAllocator<uint8_t>>;

struct BufferObject {
  DataStore data;  // the data store; its size is GL_BUFFER_SIZE
  GLenum usage = GL_STATIC_DRAW;
  // The mapping (glMapBuffer maps the whole store, glMapBufferRange a range
  // of it; GL 3.0 §2.10.1): its GL_MAP_*_BIT flags (GL_BUFFER_ACCESS_FLAGS),
  // GL_BUFFER_MAP_OFFSET, GL_BUFFER_MAP_LENGTH and GL_BUFFER_MAP_POINTER, the
  // address of the range's first byte. All 0 while unmapped.
  bool mapped = false;
  GLbitfield accessFlags = 0;
  GLintptr mapOffset = 0;
  GLsizeiptr mapLength = 0;
  void* mapPointer = nullptr;
  GLsizeiptr size() const { return static_cast<GLsizeiptr>(data.size()); }
  // GL_BUFFER_ACCESS, from the flags: READ_WRITE while unmapped, as Mesa
  // answers after glUnmapBuffer (GL 3.0 keeps the last glMapBuffer's).
  GLenum access() const {
    const bool read = accessFlags & GL_MAP_READ_BIT, write = accessFlags & GL_MAP_WRITE_BIT;
    return read && !write ? GL_READ_ONLY : write && !read ? GL_WRITE_ONLY : GL_READ_WRITE;
  }
  // True if [offset, offset + length) meets the mapped range.
  bool rangeMapped(GLintptr offset, GLsizeiptr length) const {
    return mapped && offset + length > mapOffset && offset < mapOffset + mapLength;
  }
  void unmap() {
    mapped = false;
    accessFlags = 0;
    mapOffset = 0;
    mapLength = 0;
    mapPointer = nullptr;
  }
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
