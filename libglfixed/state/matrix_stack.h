// A matrix stack of GL 2.1 §2.11.2: the top is the current matrix.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace glfixed {

class MatrixStack {
 public:
  explicit MatrixStack(int maxDepth) : maxDepth_(maxDepth) {
    stack_.reserve(maxDepth);
    stack_.emplace_back(1.0f);
    changed_.push_back(false);
  }
  glm::mat4& top() { return stack_.back(); }
  const glm::mat4& top() const { return stack_.back(); }
  int depth() const { return static_cast<int>(stack_.size()); }
  int maxDepth() const { return maxDepth_; }
  bool push() {  // false: GL_STACK_OVERFLOW
    if (depth() >= maxDepth_) return false;
    stack_.push_back(stack_.back());
    changed_.push_back(false);
    return true;
  }
  bool pop() {  // false: GL_STACK_UNDERFLOW
    if (depth() <= 1) return false;
    stack_.pop_back();
    changed_.pop_back();
    return true;
  }
  // Whether the top was loaded or multiplied since the glPushMatrix that made
  // it (Mesa's ChangedSincePush): glPopMatrix flushes the buffered vertices
  // only then, and glPushMatrix never does.
  void markChanged() { changed_.back() = true; }
  bool changedSincePush() const { return changed_.back(); }

 private:
  int maxDepth_;
  std::vector<glm::mat4> stack_;
  std::vector<bool> changed_;
};

}  // namespace glfixed
