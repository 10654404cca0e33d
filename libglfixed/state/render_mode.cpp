#include "state/render_mode.h"

namespace glfixed {

namespace {

// GL 2.1 §5.2 maps the z range [0,1] onto [0, 2^32-1]. Mesa (feedback.c,
// write_hit_record) multiplies in float by (GLfloat)0xffffffff, which is
// 2^32, and converts to GLuint as x86-64 GCC does: through a 64-bit integer,
// keeping the low 32 bits, so z = 1.0 gives 0. Measured: select_pick.
GLuint scaledDepth(float z) {
  const float scaled = 4294967296.0f * z;
  if (!(scaled >= 0.0f)) return 0;
  if (scaled >= 9223372036854775808.0f) return 0;
  return static_cast<GLuint>(static_cast<uint64_t>(static_cast<int64_t>(scaled)));
}

}  // namespace

void SelectState::writeHitRecord() {
  write(static_cast<GLuint>(nameStackDepth));
  write(scaledDepth(hitMinZ));
  write(scaledDepth(hitMaxZ));
  for (int i = 0; i < nameStackDepth; ++i) write(nameStack[i]);
  ++hits;
  hitFlag = false;
  hitMinZ = 1.0f;
  hitMaxZ = -1.0f;
}

}  // namespace glfixed
