// The lighting stage's part of glGet*: every query of the lighting state
// lives here, next to the state it reads (its capabilities are in
// state/capabilities.cpp's table).
#pragma once

#include <GL/gl.h>

namespace glfixed {

class Context;

// Fills `out` (up to 16 values) and `*count` for a lighting pname; false for a
// pname the lighting stage does not own.
bool getLightingState(Context& ctx, GLenum pname, GLdouble* out, int* count);

}  // namespace glfixed
