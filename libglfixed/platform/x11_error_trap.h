// X errors raised by the library's own requests are caught here, not left to
// the program's handler (whose default exits). The handler is process-wide:
// one trapped request sequence at a time.
#pragma once

#include <X11/Xlib.h>

#include <mutex>

namespace glfixed::platform {

class ErrorTrap {
 public:
  explicit ErrorTrap(Display* display);  // syncs: earlier errors stay the program's
  ~ErrorTrap();
  ErrorTrap(const ErrorTrap&) = delete;
  ErrorTrap& operator=(const ErrorTrap&) = delete;
  // Waits for the server, then tells whether one of our requests failed.
  bool failed();

 private:
  Display* display_;
  std::lock_guard<std::recursive_mutex> lock_;
  int (*previous_)(Display*, XErrorEvent*) = nullptr;
  bool previousTrapped_ = false;
};

}  // namespace glfixed::platform
