// For glGetPointerv (GL 2.1 §6.1.11): the buffers of glSelectBuffer and
// glFeedbackBuffer.
#pragma once

#include <GL/gl.h>

namespace glfixed {
class Context;
}

namespace glfixed::api {

// GL_SELECTION_BUFFER_POINTER, GL_FEEDBACK_BUFFER_POINTER: stores the pointer
// and returns true; any other pname: false.
bool renderModePointer(const Context& ctx, GLenum pname, void** params);

}  // namespace glfixed::api
