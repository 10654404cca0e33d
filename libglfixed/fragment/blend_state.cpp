#include "fragment/blend_state.h"

#include "raster/raster.h"

namespace glfixed::fragment {

BlendState makeBlendState(bool blend, GLenum srcRGB, GLenum dstRGB, GLenum srcAlpha, GLenum dstAlpha,
                          GLenum equationRGB, GLenum equationAlpha, const float color[4], bool logicOpEnabled,
                          GLenum logicOp) {
  BlendState b;
  // §4.1.10: the logic op, when enabled, replaces blending.
  if (logicOpEnabled) {
    if (logicOp != GL_COPY) {
      b.mode = BlendState::Mode::kLogicOp;
      b.logicOp = logicOp;
    }
    return b;
  }
  if (!blend) return b;
  const bool plain = srcRGB == GL_ONE && dstRGB == GL_ZERO && srcAlpha == GL_ONE && dstAlpha == GL_ZERO &&
                     equationRGB == GL_FUNC_ADD && equationAlpha == GL_FUNC_ADD;
  if (plain) return b;  // src * 255 / 255 rounds back to src exactly
  b.mode = BlendState::Mode::kBlend;
  b.srcRGB = srcRGB;
  b.dstRGB = dstRGB;
  b.srcAlpha = srcAlpha;
  b.dstAlpha = dstAlpha;
  b.equationRGB = equationRGB;
  b.equationAlpha = equationAlpha;
  // llvmpipe: the constant colour as 8 bits, clamped and rounded as a
  // fragment's colour (rint(c * 255): 0.5 gives 128, 0.3 gives 76).
  for (int k = 0; k < 4; ++k) b.constant[k] = raster::colorToUnorm8(color[k]);
  for (int k = 0; k < 4; ++k)
    b.constantFloat[k] = color[k] > 0.0f ? (color[k] < 1.0f ? color[k] : 1.0f) : 0.0f;
  return b;
}

}  // namespace glfixed::fragment
