// Blending and the logic op (GL 2.1 §4.1.8, §4.1.10) as a draw's fragments
// see them: a snapshot of the colour buffer state, in the 8-bit terms
// llvmpipe blends unorm8 buffers in (fragment/blend.inc).
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed::fragment {

struct BlendState {
  // What runs before the colour write: nothing (the fragment's colour as
  // it is), blending, or the logic op (which replaces blending, §4.1.10).
  enum class Mode : uint8_t { kNone, kBlend, kLogicOp };
  Mode mode = Mode::kNone;
  GLenum srcRGB = GL_ONE, dstRGB = GL_ZERO, srcAlpha = GL_ONE, dstAlpha = GL_ZERO;
  GLenum equationRGB = GL_FUNC_ADD, equationAlpha = GL_FUNC_ADD;
  GLenum logicOp = GL_COPY;
  // glBlendColor clamped and rounded to 8 bits as a fragment colour is.
  int32_t constant[4] = {0, 0, 0, 0};
  // The same clamped to [0, 1], for 16-bit and float buffers (wide_color.inc).
  float constantFloat[4] = {0, 0, 0, 0};
};

// The snapshot of the context's colour buffer state (GL_BLEND, the factors,
// equations and colour; GL_COLOR_LOGIC_OP and its op). Mode::kNone where the
// result is the fragment's colour anyway (GL_COPY; ONE, ZERO, FUNC_ADD).
BlendState makeBlendState(bool blend, GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha,
                          GLenum equationRGB, GLenum equationAlpha, const float color[4], bool logicOpEnabled,
                          GLenum logicOp);

}  // namespace glfixed::fragment
