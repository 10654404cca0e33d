// Points (GL 2.1 §3.4): assembly, clipping and the hand-over to llvmpipe's
// point setup. Not rasterized yet (issue 12): a point batch draws nothing.
#include "primitive/batch_context.h"

namespace glfixed::primitive {

void drawPointBatch(BatchContext&, uint32_t, const std::vector<ClipVertex>&, const std::vector<uint32_t>&) {}

void emitPoint(const BatchContext&, const ClipVertex&) {}

}  // namespace glfixed::primitive
