// The one recording hook of display lists (GL 2.1 §5.4). Every listable entry
// point starts with one line that hands itself and its arguments to it:
//
//   GLAPI void APIENTRY glDepthFunc(GLenum func) {
//     if (api::compiled(&glDepthFunc, func)) return;
//     ... the command as it runs ...
//
// While no list is being compiled (or while a list executes) compiled()
// returns false and the command runs. Between glNewList and glEndList the call
// is stored: the entry point and its arguments by value, pointer arguments
// wrapped in copied(pointer, count) so that the values are the ones in effect
// at compile time (§5.4: client state is captured then). A replay calls the
// same entry point again, so a listable command has one implementation. The
// return is true in GL_COMPILE (the caller returns) and false in
// GL_COMPILE_AND_EXECUTE (the caller goes on and runs the command).
//
// Commands that are executed at once and never compiled (§5.4: glGet*,
// glIsList, glGenLists, glDeleteLists, glFeedbackBuffer, glSelectBuffer,
// glRenderMode, glReadPixels, glPixelStore, glFlush, glFinish, the client
// state commands, ...) simply have no hook. Vertex data has its own variants
// below, because between the list's glBegin and glEnd it joins a vertex node
// (pipeline/display_list.h) instead of being stored as calls.
//
// glDrawArrays/glDrawElements must capture the array contents at compile
// time (§5.4): while a list compiles (api::listCompiler(ctx) non-null, not
// inside the list's glBegin/glEnd) they validate mode and count as a compiled
// error would (ListCompiler::recordError), then fetch each element into the
// node, ListCompiler::begin(mode), color()/normal() for the enabled arrays,
// vertex(), end(), the way Mesa's save_DrawArrays loops over
// _mesa_array_element; in GL_COMPILE_AND_EXECUTE the node is fed back at its
// end like any other.
//
// A few commands Mesa runs before it compiles them, or does not compile when
// they repeat the list's last value (glShadeModel, glMaterial outside
// glBegin/glEnd): they use runUnrecorded() and ListCompiler's known state
// instead of the one line (api/gl_light_api.cpp).
#pragma once

#include <GL/gl.h>

#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "pipeline/display_list.h"
#include "state/context.h"

namespace glfixed::api {

template <typename T>
struct Copied {
  const T* data;
  size_t count;
};
// A pointer argument of a compiled command: its first `count` values.
template <typename T>
Copied<T> copied(const T* data, size_t count) {
  return {data, count};
}

namespace detail {
template <typename T>
struct StoredArray {
  std::vector<T> values;
  bool null;
};
template <typename A>
std::decay_t<A> keep(const A& a) {
  return a;
}
template <typename T>
StoredArray<T> keep(const Copied<T>& c) {
  return {c.data ? std::vector<T>(c.data, c.data + c.count) : std::vector<T>(), c.data == nullptr};
}
template <typename A>
const A& pass(const A& a) {
  return a;
}
template <typename T>
const T* pass(const StoredArray<T>& a) {
  return a.null ? nullptr : a.values.data();
}
}  // namespace detail

// The list being compiled, if commands must be recorded now.
inline pipeline::ListCompiler* listCompiler(Context* ctx) {
  if (!ctx || !ctx->displayLists.compiler || ctx->displayLists.executing) return nullptr;
  return ctx->displayLists.compiler.get();
}

// Stores a call of `fn` in the list being compiled (see above).
template <typename R, typename... P, typename... A>
bool compiled(R (*fn)(P...), const A&... args) {
  Context* ctx = currentContext();
  pipeline::ListCompiler* list = listCompiler(ctx);
  if (!list) return false;
  if (list->insideBeginEnd()) {  // not allowed between glBegin and glEnd (§2.6.3)
    list->recordError(*ctx, GL_INVALID_OPERATION);
    return true;
  }
  list->record([fn, stored = std::make_tuple(detail::keep(args)...)] {
    std::apply([fn](const auto&... s) { fn(detail::pass(s)...); }, stored);
  });
  return !list->executes();
}

// Vertex data (glVertex, glColor, glNormal): inside the list's glBegin/glEnd,
// `intoNode(ListCompiler&)` adds it to the vertex node and it is not run now
// (GL_COMPILE_AND_EXECUTE runs the node when it ends); outside, it is a
// command like any other.
template <typename Node, typename R, typename... P, typename... A>
bool compiledVertexData(Node&& intoNode, R (*fn)(P...), const A&... args) {
  pipeline::ListCompiler* list = listCompiler(currentContext());
  if (!list) return false;
  if (list->insideBeginEnd()) {
    intoNode(*list);
    return true;
  }
  return compiled(fn, args...);
}

// A current attribute no stage reads per vertex yet (texture coordinates,
// secondary colour, fog coordinate, colour index, edge flag): inside the
// list's glBegin/glEnd it is run after the node's vertices.
template <typename R, typename... P, typename... A>
bool compiledAttribute(R (*fn)(P...), const A&... args) {
  pipeline::ListCompiler* list = listCompiler(currentContext());
  if (!list) return false;
  if (list->insideBeginEnd()) {
    list->attributeCall([fn, stored = std::make_tuple(detail::keep(args)...)] {
      std::apply([fn](const auto&... s) { fn(detail::pass(s)...); }, stored);
    });
    return true;
  }
  return compiled(fn, args...);
}

// A command that issues other commands (glEvalMesh issues glBegin,
// glEvalCoord and glEnd): as compiled(), but in GL_COMPILE_AND_EXECUTE it
// runs here, unrecorded, so that the commands it issues are not compiled
// too. True whenever a list is being compiled (the caller returns).
template <typename R, typename... P, typename... A>
bool compiledCompound(R (*fn)(P...), const A&... args);

// A draw from the vertex arrays (glDrawArrays, glDrawElements, ...): in a
// list it is the glBegin/glEnd it stands for, `intoNode(ListCompiler&)`
// reading the elements now (§5.4: array contents are captured at compile
// time) and feeding them to the vertex node, as Mesa's save_DrawArrays
// loops over _mesa_array_element. Not allowed inside the list's
// glBegin/glEnd. True whenever a list is being compiled.
template <typename Node>
bool compiledDraw(Node&& intoNode) {
  Context* ctx = currentContext();
  pipeline::ListCompiler* list = listCompiler(ctx);
  if (!list) return false;
  if (list->insideBeginEnd())
    list->recordError(*ctx, GL_INVALID_OPERATION);
  else
    intoNode(*list);
  return true;
}

// Runs a command now without recording it (for the few that Mesa executes
// before it compiles them).
template <typename R, typename... P, typename... A>
void runUnrecorded(R (*fn)(P...), const A&... args) {
  Context* ctx = currentContext();
  if (!ctx) return;
  ++ctx->displayLists.executing;
  fn(args...);
  --ctx->displayLists.executing;
}

template <typename R, typename... P, typename... A>
bool compiledCompound(R (*fn)(P...), const A&... args) {
  pipeline::ListCompiler* list = listCompiler(currentContext());
  if (!list) return false;
  if (!compiled(fn, args...)) runUnrecorded(fn, args...);
  return true;
}

}  // namespace glfixed::api
