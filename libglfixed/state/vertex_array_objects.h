// Vertex array objects (ARB_vertex_array_object; GL 3.0 §2.10): named
// copies of the arrays' state. The bound object's state lives in the
// context's VertexArrayAttrib (the stages read it there); binding another
// object stores it here and loads the other. Objects belong to one context,
// never to its share group (ARB_vertex_array_object's issue 1; Mesa alike:
// reference/MESA_FACTS.md, "Vertex array objects").
#pragma once

#include <GL/gl.h>

#include <map>

#include "state/vertex_array_attrib.h"

namespace glfixed {

class VertexArrayObjects {
 public:
  // Names not in use, none of them 0 (glGenVertexArrays): they name objects
  // at once, but glIsVertexArray says so only once they were bound.
  void generate(GLsizei n, GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) {
      while (objects_.count(next_)) ++next_;
      objects_[next_] = Object{};
      names[i] = next_++;
    }
  }
  // A name glBindVertexArray accepts: 0 or a generated, undeleted name.
  bool bindable(GLuint name) const { return name == 0 || objects_.count(name); }
  bool isVertexArray(GLuint name) const {
    auto it = objects_.find(name);
    return it != objects_.end() && it->second.everBound;
  }
  // Makes `name` (bindable) the bound object of `live`, the context's arrays.
  void bind(VertexArrayAttrib& live, GLuint name) {
    if (name == live.vertexArrayBinding) return;
    slot(live.vertexArrayBinding).state = live;  // the object part only
    Object& o = slot(name);
    o.everBound = true;
    static_cast<VertexArrayObjectState&>(live) = o.state;
    live.vertexArrayBinding = name;
  }
  // glDeleteVertexArrays of one name: deleting the bound object binds 0 first.
  void remove(VertexArrayAttrib& live, GLuint name) {
    if (name == 0 || !objects_.count(name)) return;
    if (name == live.vertexArrayBinding) bind(live, 0);
    objects_.erase(name);
  }
  // Every stored object's state (the bound one's is the context's).
  template <typename F>
  void forEachStored(F&& f) {
    f(default_.state);
    for (auto& [name, o] : objects_) f(o.state);
  }

 private:
  struct Object {
    VertexArrayObjectState state;
    bool everBound = false;
  };
  Object& slot(GLuint name) { return name == 0 ? default_ : objects_[name]; }

  Object default_;
  std::map<GLuint, Object> objects_;
  GLuint next_ = 1;
};

}  // namespace glfixed
