// Clearing and reading back the framebuffer.
#pragma once

#include <GL/gl.h>

#include <cstddef>

#include "framebuffer/framebuffer.h"
#include "state/attrib_groups.h"
#include "state/attribs.h"
#include "state/pixel_maps.h"

namespace glfixed {

// A box of pixels [x0, x1) x [y0, y1), GL window coordinates (y up).
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// The pixels of the framebuffer inside the scissor box when the scissor test
// is on (GL 2.1 §4.1.2): what glClear and glAccum touch.
PixelBox scissoredBox(const Framebuffer& fb, const ScissorAttrib& scissor);

// glClear of the colour buffer: the pixels of `box` (inside the buffer),
// honouring the colour write mask.
void clearColor(const ColorBuffer& buffer, const ColorBufferAttrib& colorBuffer, const PixelBox& box);
// glClear of the depth buffer: `value` into the pixels of `box`.
void clearDepth(Framebuffer& fb, uint32_t value, const PixelBox& box);
// glClear of the stencil buffer: `value` into the pixels of `box`, the bits of `writeMask` only.
void clearStencil(Framebuffer& fb, uint32_t value, uint32_t writeMask, const PixelBox& box);

// glReadPixels (GL 2.1 §4.3.2): returns the GL error to record, or GL_NO_ERROR.
// Pixels outside the framebuffer are left untouched in `pixels`.
// The bytes glReadPixels writes from its pointer on, up to the last one
// (the pack parameters' skips, row length and alignment); 0 if none.
size_t packedImageBytes(const PixelStoreAttrib& pack, GLsizei width, GLsizei height, GLenum format,
                        GLenum type);

// The pixel transfer of `transfer` (§3.6.5, §4.3.2), as Mesa's
// _mesa_readpixels does it: stencil values through the stencil index
// transfer (framebuffer/stencil_index.h), depths through GL_DEPTH_SCALE and
// GL_DEPTH_BIAS, colour through the scale, bias and (with `maps`)
// GL_MAP_COLOR, then clamped to [0, 1], except colour read as GL_FLOAT.
GLenum readPixels(const Framebuffer& fb, const PixelStoreAttrib& pack, GLint x, GLint y, GLsizei width,
                  GLsizei height, GLenum format, GLenum type, void* pixels,
                  const PixelModeAttrib& transfer = PixelModeAttrib(), const PixelMaps* maps = nullptr);

}  // namespace glfixed
