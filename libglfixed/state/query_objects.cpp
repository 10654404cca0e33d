#include "state/query_objects.h"

namespace glfixed {

void QueryObjects::generate(GLsizei n, GLuint* names) {
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (objects_.count(next)) ++next;
    objects_[next] = QueryObject();
    names[i] = next;
  }
}

void QueryObjects::remove(GLuint name) {
  if (name == 0) return;
  if (active_ == name) end();
  objects_.erase(name);
}

QueryObject* QueryObjects::find(GLuint name) {
  auto it = objects_.find(name);
  return it == objects_.end() ? nullptr : &it->second;
}

bool QueryObjects::isQuery(GLuint name) const {
  auto it = objects_.find(name);
  return it != objects_.end() && it->second.everActive;
}

QueryObject& QueryObjects::begin(GLuint name) {
  QueryObject& q = objects_[name];
  q.everActive = true;
  q.samplesPassed = 0;
  active_ = name;
  counter_ = &q.samplesPassed;
  return q;
}

}  // namespace glfixed
