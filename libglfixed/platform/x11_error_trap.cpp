#include "platform/x11_error_trap.h"

namespace glfixed::platform {

namespace {

// Recursive: a trapped GLX call may itself call a trapped helper
// (x11DrawableSize) on the same thread.
std::recursive_mutex gErrorTrapMutex;
bool gErrorTrapped = false;
int trapError(Display*, XErrorEvent*) {
  gErrorTrapped = true;
  return 0;
}

}  // namespace

ErrorTrap::ErrorTrap(Display* display) : display_(display), lock_(gErrorTrapMutex) {
  XSync(display_, False);
  previousTrapped_ = gErrorTrapped;
  gErrorTrapped = false;
  previous_ = XSetErrorHandler(trapError);
}

ErrorTrap::~ErrorTrap() {
  XSync(display_, False);  // our errors arrive while our handler is in place
  XSetErrorHandler(previous_);
  gErrorTrapped = previousTrapped_ || gErrorTrapped;
}

bool ErrorTrap::failed() {
  XSync(display_, False);
  return gErrorTrapped;
}

}  // namespace glfixed::platform
