// Display list entry points (GL 2.1 §5.4): glNewList, glEndList, glCallList,
// glCallLists, glListBase, glGenLists, glDeleteLists, glIsList. The list store
// and the compiler are pipeline/display_list.h; the recording hook of every
// other command is api/list_record.h.
#include <cstring>

#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

namespace {

// The bytes one name of glCallLists takes, or 0 for a bad type.
size_t nameSize(GLenum type) {
  switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_2_BYTES: return 2;
    case GL_3_BYTES: return 3;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT:
    case GL_4_BYTES: return 4;
    default: return 0;
  }
}

// Name i of glCallLists' array, before the list base is added (§5.4).
GLuint nameAt(const void* lists, GLenum type, GLsizei i) {
  const unsigned char* b = static_cast<const unsigned char*>(lists) + static_cast<size_t>(i) * nameSize(type);
  switch (type) {
    case GL_BYTE: return static_cast<GLuint>(static_cast<GLint>(*reinterpret_cast<const GLbyte*>(b)));
    case GL_UNSIGNED_BYTE: return *b;
    case GL_SHORT: {
      GLshort v;
      std::memcpy(&v, b, 2);
      return static_cast<GLuint>(static_cast<GLint>(v));
    }
    case GL_UNSIGNED_SHORT: {
      GLushort v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case GL_INT: {
      GLint v;
      std::memcpy(&v, b, 4);
      return static_cast<GLuint>(v);
    }
    case GL_UNSIGNED_INT: {
      GLuint v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case GL_FLOAT: {
      GLfloat v;
      std::memcpy(&v, b, 4);
      return static_cast<GLuint>(static_cast<GLint>(v));
    }
    case GL_2_BYTES: return b[0] * 256u + b[1];
    case GL_3_BYTES: return (b[0] * 256u + b[1]) * 256u + b[2];
    case GL_4_BYTES: return ((b[0] * 256u + b[1]) * 256u + b[2]) * 256u + b[3];
    default: return 0;
  }
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glNewList(GLuint list, GLenum mode) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (list == 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (ctx->displayLists.compiler) {  // glNewList while a list is compiled
    ctx->recordError(GL_INVALID_OPERATION);
    return;
  }
  ctx->displayLists.compiler = std::make_unique<pipeline::ListCompiler>(list, mode);
}

GLAPI void APIENTRY glEndList(void) {
  // While a list compiles, glBegin/glEnd go to the list: the immediate mode is
  // between glBegin and glEnd only while GL_COMPILE_AND_EXECUTE feeds back a
  // primitive the list has not ended yet, which finishing the list ends.
  Context* ctx = api::context();
  if (!ctx) return;
  if (!ctx->displayLists.compiler) {
    ctx->recordError(GL_INVALID_OPERATION);
    return;
  }
  // The new contents replace the list's old ones only now (§5.4).
  std::unique_ptr<pipeline::ListCompiler> compiler = std::move(ctx->displayLists.compiler);
  ctx->displayLists.install(compiler->name(), compiler->finish());
  // A GL_COMPILE_AND_EXECUTE list that ends inside glBegin/glEnd leaves
  // Mesa outside them, its unfinished primitive undrawn (a glEnd next is
  // GL_INVALID_OPERATION); a glCallList of that list, by contrast, leaves the
  // primitive open for the vertices that follow.
  if (compiler->executes() && ctx->insideBeginEnd) {
    ctx->batch.clearVertices();
    ctx->insideBeginEnd = false;
    pipeline::endPrimitive(*ctx);
  }
}

// Allowed between glBegin and glEnd (§2.6.3).
GLAPI void APIENTRY glCallList(GLuint list) {
  Context* ctx = api::context();
  if (!ctx) return;
  if (pipeline::ListCompiler* compiler = api::listCompiler(ctx)) {
    if (compiler->insideBeginEnd()) compiler->fallBackToCommands();
    compiler->record([list] { glCallList(list); });
    compiler->forgetKnownState();  // the called list may change any state
    if (!compiler->executes()) return;
  }
  ctx->displayLists.call(list);
}

GLAPI void APIENTRY glCallLists(GLsizei n, GLenum type, const GLvoid* lists) {
  Context* ctx = api::context();
  if (!ctx) return;
  const size_t size = nameSize(type);
  if (pipeline::ListCompiler* compiler = api::listCompiler(ctx)) {
    // The names are copied now; the list base is the one at execution.
    if (compiler->insideBeginEnd()) compiler->fallBackToCommands();
    const size_t bytes = (n > 0 && lists) ? size * static_cast<size_t>(n) : 0;
    const unsigned char* b = static_cast<const unsigned char*>(lists);
    compiler->record(
        [n, type, names = std::vector<unsigned char>(b, b + bytes), hadNames = lists != nullptr] {
          glCallLists(n, type,
                      hadNames ? (names.empty() ? static_cast<const void*>(&names) : names.data()) : nullptr);
        });
    compiler->forgetKnownState();
    if (!compiler->executes()) return;
  }
  if (n < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  if (size == 0) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  if (!lists) return;
  for (GLsizei i = 0; i < n; ++i) ctx->displayLists.call(ctx->list.base + nameAt(lists, type, i));
}

GLAPI void APIENTRY glListBase(GLuint base) {
  if (api::compiled(&glListBase, base)) return;
  Context* ctx = api::contextForSetter();
  if (ctx) api::setState(*ctx, ctx->list.base, base, GL_LIST_BIT);
}

// Executed at once, never compiled (§5.4).
GLAPI GLuint APIENTRY glGenLists(GLsizei range) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return 0;
  if (range < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return 0;
  }
  return ctx->displayLists.genLists(range);
}

GLAPI void APIENTRY glDeleteLists(GLuint list, GLsizei range) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (range < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return;
  }
  ctx->displayLists.deleteLists(list, range);
}

GLAPI GLboolean APIENTRY glIsList(GLuint list) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  return ctx->displayLists.isList(list) ? GL_TRUE : GL_FALSE;
}

}  // extern "C"
