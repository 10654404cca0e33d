// The framebuffer object bindings of a context (GL 3.0 §4.4.1): which
// framebuffer the stages draw into and read from, rebuilt from the objects'
// attachments before every use, so that a texture redefined or a
// renderbuffer reallocated since is seen as it is now.
#pragma once

#include <GL/gl.h>

#include "state/context.h"

namespace glfixed {

// Binds the draw and read framebuffers (0: the window system's), parking or
// restoring the window's buffers, and loading each object's draw and read
// buffer into the GL state.
void bindFramebuffers(Context& ctx, GLuint draw, GLuint read);

// Rebuilds ctx.framebuffer from the bound objects (nothing to do when none
// is bound) and their status (ctx.fbo.drawStatus, readStatus).
void refreshFramebuffer(Context& ctx);

// For a command that draws (or clears): refreshes, and records
// GL_INVALID_FRAMEBUFFER_OPERATION and returns false when the draw
// framebuffer is incomplete. The same for reading, of the read framebuffer.
bool drawFramebufferComplete(Context& ctx);
bool readFramebufferComplete(Context& ctx);

// The object bound as the draw (read) framebuffer, or null.
FramebufferObject* drawFramebufferObject(Context& ctx);
FramebufferObject* readFramebufferObject(Context& ctx);

}  // namespace glfixed
