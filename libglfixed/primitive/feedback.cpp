// Every float operation here must round as Mesa's does.
#pragma GCC optimize("fp-contract=off")

#include "primitive/select_feedback.h"
#include "primitive/unrasterized.h"

namespace glfixed::primitive {

namespace {

class FeedbackSink final : public PrimitiveSink {
 public:
  FeedbackSink(FeedbackState& feedback, int framebufferHeight, bool flipY, const glm::vec4& texCoord,
               bool perVertex)
      : fb_(feedback), height_(static_cast<float>(framebufferHeight)), flipY_(flipY), texCoord_(texCoord),
        perVertexTexCoord_(perVertex) {}

  void point(const ClipVertex& v) override {
    fb_.token(static_cast<GLfloat>(GL_POINT_TOKEN));
    vertex(v, kSinkFrontColor);
  }
  void line(const ClipVertex& v0, const ClipVertex& v1) override {
    fb_.token(static_cast<GLfloat>(GL_LINE_TOKEN));
    vertex(v0, kSinkFrontColor);
    vertex(v1, kSinkFrontColor);
  }
  void triangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, int color) override {
    fb_.token(static_cast<GLfloat>(GL_POLYGON_TOKEN));
    fb_.token(3.0f);
    vertex(v0, color);
    vertex(v1, color);
    vertex(v2, color);
  }

 private:
  // st_cb_feedback.c, feedback_vertex: the draw module's window y is down
  // from the top (viewport.h), so y = height - y, but in a framebuffer
  // object (Y_0_BOTTOM) it is GL's; w = 1 / (1/w), in float.
  void vertex(const ClipVertex& v, int color) {
    fb_.token(v.window[0]);
    fb_.token(flipY_ ? height_ - v.window[1] : v.window[1]);
    const GLenum type = fb_.type;
    if (type != GL_2D) fb_.token(v.window[2]);
    if (type == GL_4D_COLOR_TEXTURE) fb_.token(1.0f / v.window[3]);
    if (type == GL_3D_COLOR || type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE)
      for (int k = 0; k < 4; ++k) fb_.token(v.attr[color + k]);
    if (type == GL_3D_COLOR_TEXTURE || type == GL_4D_COLOR_TEXTURE)
      for (int k = 0; k < 4; ++k) fb_.token(perVertexTexCoord_ ? v.attr[kSinkTexCoord + k] : texCoord_[k]);
  }

  FeedbackState& fb_;
  float height_;
  bool flipY_;
  glm::vec4 texCoord_;
  // Texture coordinates (issue 14): each vertex's unit-0 coordinates from
  // the vertex stage (after texgen and the texture matrix, clipped ones
  // interpolated), else `texCoord_` for all.
  bool perVertexTexCoord_;
};

}  // namespace

void feedbackPrimitives(const PrimitiveState& state, const ShadedVertices& vertices, int framebufferHeight,
                        const glm::vec4& texCoord, FeedbackState& feedback) {
  FeedbackSink sink(feedback, framebufferHeight, state.flipViewportY, texCoord, (vertices.texCoordUnits & 1u) != 0);
  drawUnrasterized(state, vertices, framebufferHeight, sink);
}

}  // namespace glfixed::primitive
