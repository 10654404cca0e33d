// Lines (GL 2.1 §3.5): assembly, clipping and the hand-over to llvmpipe's
// line setup. Not rasterized yet (issue 12): a line batch draws nothing.
#include "primitive/batch_context.h"

namespace glfixed::primitive {

void drawLineBatch(BatchContext&, GLenum, uint32_t, const std::vector<ClipVertex>&,
                   const std::vector<uint32_t>&) {}

void emitLine(const BatchContext&, const ClipVertex&, const ClipVertex&, const ClipVertex&) {}

}  // namespace glfixed::primitive
