// The lighting stage's part of glEnable/glIsEnabled/glGet*: every capability
// and query of the lighting state lives here, next to the state it reads.
#pragma once

#include <GL/gl.h>

namespace glfixed {

class Context;

// Fills `out` (up to 16 values) and `*count` for a lighting pname; false for a
// pname the lighting stage does not own.
bool getLightingState(Context& ctx, GLenum pname, GLdouble* out, int* count);

// glEnable/glDisable of GL_LIGHTING, GL_LIGHTi, GL_COLOR_MATERIAL, GL_NORMALIZE,
// GL_RESCALE_NORMAL; false for a capability the lighting stage does not own.
bool setLightingCapability(Context& ctx, GLenum cap, bool enabled);

}  // namespace glfixed
