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

// XSync only when a request may still be unanswered: when the server has
// processed every request sent, every error it raised has been read
// already. (A swap used to wait for six round trips, four of them empty.)
void syncIfPending(Display* display) {
  if (NextRequest(display) - 1 != LastKnownRequestProcessed(display)) XSync(display, False);
}

}  // namespace

ErrorTrap::ErrorTrap(Display* display) : display_(display), lock_(gErrorTrapMutex) {
  syncIfPending(display_);
  previousTrapped_ = gErrorTrapped;
  gErrorTrapped = false;
  previous_ = XSetErrorHandler(trapError);
}

ErrorTrap::~ErrorTrap() {
  syncIfPending(display_);  // our errors arrive while our handler is in place
  XSetErrorHandler(previous_);
  gErrorTrapped = previousTrapped_ || gErrorTrapped;
}

bool ErrorTrap::failed() {
  syncIfPending(display_);
  return gErrorTrapped;
}

}  // namespace glfixed::platform
