// Brings a surface's front buffer to an X11 window or pixmap: XShmPutImage
// where the server offers MIT-SHM to this client, XPutImage otherwise; and
// asks the window's size (XGetGeometry) so that a resized window gets
// buffers of its size, as Mesa's drisw asks at swaps and glViewport.
#pragma once

#include <X11/Xlib.h>

#include <memory>

#include "platform/surface.h"

namespace glfixed::platform {

// Null (with a message on stderr) when `drawable` is not a drawable of a
// depth-24 or depth-32 TrueColor visual, the only pixels the surfaces hold.
// `visual` is the one the drawable was made with (for a pixmap, whose
// visual X does not keep); null: asked from the window.
std::unique_ptr<Presenter> makeX11Presenter(Display* display, Drawable drawable, Visual* visual);

// The drawable's size, or false if it is not a drawable (destroyed, or never
// one): the X error is caught, not left to the program's handler.
bool x11DrawableSize(Display* display, Drawable drawable, int* width, int* height, int* depth);

}  // namespace glfixed::platform
