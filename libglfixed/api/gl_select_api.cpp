// Selection and feedback (GL 2.1 §5.2, §5.3): glRenderMode, the name stack,
// glSelectBuffer, glFeedbackBuffer, glPassThrough. Each command is a plain
// function of its arguments (display lists record glInitNames, glLoadName,
// glPushName, glPopName and glPassThrough; glRenderMode, glSelectBuffer and
// glFeedbackBuffer are never compiled, §5.4).
#include "api/gl_select_api.h"

#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

namespace {

bool isFeedbackType(GLenum type) {
  switch (type) {
    case GL_2D:
    case GL_3D:
    case GL_3D_COLOR:
    case GL_3D_COLOR_TEXTURE:
    case GL_4D_COLOR_TEXTURE: return true;
    default: return false;
  }
}

// The name-stack commands act in GL_SELECT only (§5.2: "ignored" otherwise,
// no error), and close the current hit record first: a primitive drawn
// before the change belongs to the old names. Outside GL_SELECT they do not
// end Mesa's buffered draw (scene names_in_render_mode).
Context* nameStackContext() {
  Context* ctx = api::contextForQuery();
  if (!ctx || ctx->renderMode.mode != GL_SELECT) return nullptr;
  pipeline::flushVertices(*ctx);
  SelectState& s = ctx->renderMode.select;
  if (s.hitFlag) s.writeHitRecord();
  return ctx;
}

}  // namespace

namespace glfixed::api {

bool renderModePointer(const Context& ctx, GLenum pname, void** params) {
  const RenderModeState& rm = ctx.renderMode;
  switch (pname) {
    case GL_SELECTION_BUFFER_POINTER:
      *params = rm.select.bufferSize > 0 ? rm.select.buffer : nullptr;
      return true;
    case GL_FEEDBACK_BUFFER_POINTER:
      *params = rm.feedback.bufferSize > 0 ? rm.feedback.buffer : nullptr;
      return true;
    default: return false;
  }
}

}  // namespace glfixed::api

extern "C" {

// Only the selection and feedback pointers so far; the vertex-array pointers
// join here when vertex arrays do.
GLAPI GLint APIENTRY glRenderMode(GLenum mode) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return 0;
  RenderModeState& rm = ctx->renderMode;
  if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
    ctx->recordError(GL_INVALID_ENUM);
    return 0;
  }
  // §5.2: SELECT before glSelectBuffer, FEEDBACK before glFeedbackBuffer.
  // (Mesa tests the buffer's size instead, and enters the mode anyway.)
  if ((mode == GL_SELECT && !rm.select.bufferGiven) || (mode == GL_FEEDBACK && !rm.feedback.bufferGiven)) {
    ctx->recordError(GL_INVALID_OPERATION);
    return 0;
  }
  GLint result = 0;
  if (rm.mode == GL_SELECT) {
    SelectState& s = rm.select;
    if (s.hitFlag) s.writeHitRecord();
    // Overflow: -1 (§5.2); the records that fitted stay in the buffer.
    result = s.bufferCount > static_cast<size_t>(s.bufferSize) ? -1 : static_cast<GLint>(s.hits);
    s.bufferCount = 0;
    s.hits = 0;
    s.nameStackDepth = 0;
  } else if (rm.mode == GL_FEEDBACK) {
    FeedbackState& f = rm.feedback;
    result = f.count > static_cast<size_t>(f.bufferSize) ? -1 : static_cast<GLint>(f.count);
    f.count = 0;
  }
  rm.mode = mode;
  return result;
}

GLAPI void APIENTRY glSelectBuffer(GLsizei size, GLuint* buffer) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  SelectState& s = ctx->renderMode.select;
  if (ctx->renderMode.mode == GL_SELECT) return ctx->recordError(GL_INVALID_OPERATION);
  if (size < 0) return ctx->recordError(GL_INVALID_VALUE);
  // A null buffer with room in it would be written: refuse it as Mesa
  // refuses it for glFeedbackBuffer (Mesa takes it here, and crashes at the
  // first hit). Null with size 0 is a buffer that overflows at once.
  if (!buffer && size > 0) return ctx->recordError(GL_INVALID_VALUE);
  s.buffer = buffer;
  s.bufferGiven = true;
  s.bufferSize = size;
  s.bufferCount = 0;
  s.resetHit();
}

GLAPI void APIENTRY glFeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
  Context* ctx = api::contextFlushed();
  if (!ctx) return;
  FeedbackState& f = ctx->renderMode.feedback;
  if (ctx->renderMode.mode == GL_FEEDBACK) return ctx->recordError(GL_INVALID_OPERATION);
  if (size < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!buffer && size > 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!isFeedbackType(type)) return ctx->recordError(GL_INVALID_ENUM);
  f.buffer = buffer;
  f.bufferGiven = true;
  f.bufferSize = size;
  f.type = type;
  f.count = 0;
}

GLAPI void APIENTRY glPassThrough(GLfloat token) {
  if (api::compiled(&glPassThrough, token)) return;
  // Outside GL_FEEDBACK: ignored, and Mesa's buffered draw goes on.
  Context* ctx = api::contextForQuery();
  if (!ctx || ctx->renderMode.mode != GL_FEEDBACK) return;
  pipeline::flushVertices(*ctx);  // the primitives before it come first
  ctx->renderMode.feedback.token(static_cast<GLfloat>(GL_PASS_THROUGH_TOKEN));
  ctx->renderMode.feedback.token(token);
}

GLAPI void APIENTRY glInitNames(void) {
  if (api::compiled(&glInitNames)) return;
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  SelectState& s = ctx->renderMode.select;
  if (ctx->renderMode.mode == GL_SELECT) {
    pipeline::flushVertices(*ctx);
    if (s.hitFlag) s.writeHitRecord();
  }
  s.nameStackDepth = 0;
  s.resetHit();
}

GLAPI void APIENTRY glLoadName(GLuint name) {
  if (api::compiled(&glLoadName, name)) return;
  Context* ctx = api::contextForQuery();
  if (!ctx || ctx->renderMode.mode != GL_SELECT) return;
  SelectState& s = ctx->renderMode.select;
  if (s.nameStackDepth == 0) return ctx->recordError(GL_INVALID_OPERATION);
  pipeline::flushVertices(*ctx);
  if (s.hitFlag) s.writeHitRecord();
  s.nameStack[s.nameStackDepth - 1] = name;
}

GLAPI void APIENTRY glPushName(GLuint name) {
  if (api::compiled(&glPushName, name)) return;
  Context* ctx = nameStackContext();
  if (!ctx) return;
  SelectState& s = ctx->renderMode.select;
  if (s.nameStackDepth >= kMaxNameStackDepth) return ctx->recordError(GL_STACK_OVERFLOW);
  s.nameStack[s.nameStackDepth++] = name;
}

GLAPI void APIENTRY glPopName(void) {
  if (api::compiled(&glPopName)) return;
  Context* ctx = nameStackContext();
  if (!ctx) return;
  SelectState& s = ctx->renderMode.select;
  if (s.nameStackDepth == 0) return ctx->recordError(GL_STACK_UNDERFLOW);
  --s.nameStackDepth;
}

}  // extern "C"
