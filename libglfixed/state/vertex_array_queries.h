// The vertex array and buffer binding state of glGet, glIsEnabled and
// glGetPointerv (GL 2.1 tables 6.6-6.8, 6.34).
#pragma once

#include <GL/gl.h>

#include "state/vertex_array_attrib.h"

namespace glfixed {

class Context;

// The array that a client-state capability (GL_VERTEX_ARRAY, ...) names; the
// texture coordinate array of the client active unit. Null: not one.
ClientArray* clientArrayOfCapability(VertexArrayAttrib& arrays, GLenum cap);
const ClientArray* clientArrayOfCapability(const VertexArrayAttrib& arrays, GLenum cap);

// The array whose pointer glGetPointerv(pname) returns; null: not one.
const ClientArray* clientArrayOfPointer(const VertexArrayAttrib& arrays, GLenum pname);

// Fills out[0..*count) for a vertex array, buffer binding or client attribute
// stack query; false if `pname` is none of those.
bool getVertexArrayState(const Context& ctx, GLenum pname, GLdouble* out, int* count);

}  // namespace glfixed
