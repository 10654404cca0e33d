// Clearing and reading back the framebuffer.
#pragma once

#include <GL/gl.h>

#include <cstddef>

#include "framebuffer/framebuffer.h"
#include "state/attribs.h"

namespace glfixed {

// glClear of the colour buffer: the whole buffer, honouring the colour write mask.
void clearColor(Framebuffer& fb, const ColorBufferAttrib& colorBuffer);

// glReadPixels (GL 2.1 §4.3.2): returns the GL error to record, or GL_NO_ERROR.
// Pixels outside the framebuffer are left untouched in `pixels`.
// The bytes glReadPixels writes from its pointer on, up to the last one
// (the pack parameters' skips, row length and alignment); 0 if none.
size_t packedImageBytes(const PixelStoreAttrib& pack, GLsizei width, GLsizei height, GLenum format,
                        GLenum type);

GLenum readPixels(const Framebuffer& fb, const PixelStoreAttrib& pack, GLint x, GLint y, GLsizei width,
                  GLsizei height, GLenum format, GLenum type, void* pixels);

}  // namespace glfixed
