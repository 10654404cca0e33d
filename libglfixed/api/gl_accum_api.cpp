// The accumulation buffer (GL 2.1 §4.2.4): glAccum and glClearAccum. The
// buffer and its arithmetic are framebuffer/accum_buffer.h; what Mesa does
// at the edges is here: an unknown op is GL_INVALID_ENUM before a missing
// buffer is GL_INVALID_OPERATION; only the scissor box is touched; nothing
// happens outside GL_RENDER; GL_ADD of 0, GL_MULT of 1 and GL_ACCUM of 0
// change nothing and are skipped.
#include <cmath>

#include "api/api.h"
#include "api/list_record.h"
#include "framebuffer/read_pixels.h"

using namespace glfixed;

namespace {

// Mesa's CLAMP(v, -1, 1): NaN is kept (and glGet returns it).
float clampSigned(float v) { return v < -1.0f ? -1.0f : (v > 1.0f ? 1.0f : v); }

}  // namespace

extern "C" {

GLAPI void APIENTRY glClearAccum(GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  if (api::compiled(&glClearAccum, r, g, b, a)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const glm::vec4 c(clampSigned(r), clampSigned(g), clampSigned(b), clampSigned(a));
  // NaN never compares equal: store it anyway, as Mesa does.
  if (!(c == ctx->accum.clearValue)) {
    ctx->markChanged(GL_ACCUM_BUFFER_BIT, 0);
    ctx->accum.clearValue = c;
  }
}

GLAPI void APIENTRY glAccum(GLenum op, GLfloat value) {
  if (api::compiled(&glAccum, op, value)) return;
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  Framebuffer& fb = ctx->framebuffer;
  if (!fb.accum.present()) {
    ctx->recordError(GL_INVALID_OPERATION);
    return;
  }
  if (ctx->renderMode.mode != GL_RENDER || !fb.hasSurface()) return;
  const PixelBox box = scissoredBox(fb, ctx->scissor);
  switch (op) {
    case GL_ADD:
      if (value != 0.0f) fb.accum.scaleOrBias(box, value, true);
      break;
    case GL_MULT:
      if (value != 1.0f) fb.accum.scaleOrBias(box, value, false);
      break;
    case GL_ACCUM:
      if (value != 0.0f) fb.accum.accumulate(fb.read, box, value, false);
      break;
    case GL_LOAD: fb.accum.accumulate(fb.read, box, value, true); break;
    case GL_RETURN: {
      const auto& m = ctx->colorBuffer.writeMask;
      const bool mask[4] = {m[0], m[1], m[2], m[3]};
      fb.accum.returnTo(fb.color, box, value, mask);
      if (fb.drawsIntoBoth(ctx->colorBuffer.drawBuffer)) fb.accum.returnTo(fb.front, box, value, mask);
      break;
    }
  }
}

}  // extern "C"
