// GLFIXED_DEBUG: what the library tells a developer on stderr (README,
// "Diagnostics"): each GL error as it is recorded, with the entry point that
// raised it, and each unimplemented entry point once (api/entry_points.cpp).
#pragma once

#include <GL/gl.h>

namespace glfixed {

// Whether GLFIXED_DEBUG is set to anything but "" or "0"; read once per process.
bool debugOutputEnabled();

// Prints "libglfixed: <error> in <entry point>" on stderr. Called only when an
// error is recorded and the variable is set, so it may be slow: it walks the
// stack to find the entry point.
[[gnu::cold, gnu::noinline]] void reportError(GLenum error);

}  // namespace glfixed
