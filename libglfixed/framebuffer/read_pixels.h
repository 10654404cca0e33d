// Clearing and reading back the framebuffer.
#pragma once

#include <GL/gl.h>

#include "framebuffer/framebuffer.h"
#include "state/attribs.h"

namespace glfixed {

// glClear of the colour buffer: the whole buffer, honouring the colour write mask.
void clearColor(Framebuffer& fb, const ColorBufferAttrib& colorBuffer);

// glReadPixels (GL 2.1 §4.3.2): returns the GL error to record, or GL_NO_ERROR.
// Pixels outside the framebuffer are left untouched in `pixels`.
GLenum readPixels(const Framebuffer& fb, const PixelStoreAttrib& pack, GLint x, GLint y, GLsizei width,
                  GLsizei height, GLenum format, GLenum type, void* pixels);

}  // namespace glfixed
