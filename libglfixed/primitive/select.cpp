#include "primitive/select_feedback.h"
#include "primitive/unrasterized.h"

namespace glfixed::primitive {

namespace {

class SelectSink final : public PrimitiveSink {
 public:
  explicit SelectSink(SelectState& select) : select_(select) {}
  void point(const ClipVertex& v) override { select_.updateHitFlag(v.window[2]); }
  void line(const ClipVertex& v0, const ClipVertex& v1) override {
    select_.updateHitFlag(v0.window[2]);
    select_.updateHitFlag(v1.window[2]);
  }
  void triangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, int) override {
    select_.updateHitFlag(v0.window[2]);
    select_.updateHitFlag(v1.window[2]);
    select_.updateHitFlag(v2.window[2]);
  }

 private:
  SelectState& select_;
};

}  // namespace

void selectPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, int framebufferHeight,
                      SelectState& select) {
  SelectSink sink(select);
  drawUnrasterized(state, vertices, framebufferHeight, sink);
}

}  // namespace glfixed::primitive
