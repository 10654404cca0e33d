// glLineWidth and glLineStipple (GL 2.1 §3.5.1, §3.5.2), as Mesa 22.3 takes
// them (main/lines.c; probed, tests/api/line_test.cpp):
//   - glLineWidth: GL_INVALID_VALUE for width <= 0; anything else, NaN and
//     infinity included, is stored as given and read back by
//     glGet(GL_LINE_WIDTH) unclamped; drawing clamps it (pipeline/draw.cpp);
//   - glLineStipple: the factor is clamped to [1, 256], never an error.
#include <algorithm>

#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

extern "C" {

GLAPI void APIENTRY glLineWidth(GLfloat width) {
  if (api::compiled(&glLineWidth, width)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (width <= 0.0f) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  api::setState(*ctx, ctx->line.width, width, GL_LINE_BIT);
}

GLAPI void APIENTRY glLineStipple(GLint factor, GLushort pattern) {
  if (api::compiled(&glLineStipple, factor, pattern)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  LineAttrib line = ctx->line;
  line.stippleRepeat = std::clamp(factor, 1, 256);
  line.stipplePattern = pattern;
  if (line.stippleRepeat == ctx->line.stippleRepeat && line.stipplePattern == ctx->line.stipplePattern)
    return;
  api::beginStateChange(*ctx, GL_LINE_BIT);
  ctx->line = line;
}

}  // extern "C"
