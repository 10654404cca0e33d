// Occlusion queries (GL 2.1 §4.1.7, ARB_occlusion_query): the query objects
// of one context (they are not shared between contexts) and the one
// GL_SAMPLES_PASSED query that may be active. The fragment stage adds the
// fragments that pass every test to the active query's counter
// (raster::RasterState::samplesPassed), so a query's result is ready as soon
// as glEndQuery returns, as llvmpipe's always is after a flush.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <map>

namespace glfixed {

struct QueryObject {
  bool everActive = false;  // glIsQuery is true only from the first glBeginQuery on
  uint64_t samplesPassed = 0;
};

class QueryObjects {
 public:
  // Names no object and no earlier glGenQueries holds (Mesa's first free keys).
  void generate(GLsizei n, GLuint* names);
  // Deleting the active query ends it first, as Mesa does.
  void remove(GLuint name);
  QueryObject* find(GLuint name);
  bool isQuery(GLuint name) const;

  // glBeginQuery: a name never generated becomes an object too (GL 2.1; only
  // core profiles refuse it). Returns the object now active.
  QueryObject& begin(GLuint name);
  void end() {
    active_ = 0;
    counter_ = nullptr;
  }
  GLuint active() const { return active_; }
  // The counter the fragment stage adds to, or null when no query is active
  // (the object's own: std::map keeps it in place).
  uint64_t* samplesPassedCounter() const { return counter_; }

 private:
  std::map<GLuint, QueryObject> objects_;  // generated names too, never active yet
  GLuint active_ = 0;
  uint64_t* counter_ = nullptr;
};

}  // namespace glfixed
