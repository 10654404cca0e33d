// Per-thread scratch storage of the stages (reused buffers: no allocation per
// draw) that stays usable to the thread's very end. A plain `thread_local`
// object is destroyed when the thread's TLS destructors run, and exit() runs
// the main thread's before the atexit handlers, which may still draw: piglit's
// teardown makes its context current again, and the flush drew into freed
// vectors (ASan, piglit longprim). Here the object lives behind a trivially
// destructible pointer: the thread's end frees it and clears the pointer, and
// a later use makes a new one (left to the process's end).
#pragma once

namespace glfixed::pipeline {

// One object of type T per thread and call site: `Site` is a type of the call
// site's own (a local struct), so that two sites never share storage.
template <typename T, typename Site>
T& threadScratch() {
  static thread_local T* object = nullptr;
  static thread_local bool released = false;
  struct Release {
    ~Release() {
      delete object;
      object = nullptr;
      released = true;
    }
  };
  if (!object) {
    object = new T();
    if (!released) {
      static thread_local Release release;  // registered once, at the first use
      (void)release;
    }
  }
  return *object;
}

}  // namespace glfixed::pipeline
