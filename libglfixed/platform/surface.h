// A window-system surface whose colour buffers the library owns: a GLX
// window, pixmap or pbuffer, an EGL window or pbuffer surface. GLX and EGL
// share it; only how the front buffer reaches the screen differs (a
// Presenter: platform/x11_present.h for X11 windows and pixmaps, none for
// pbuffers).
//
// The pixels are kept as a depth-24 X11 TrueColor image holds them (blue,
// green, red, then alpha or an unused byte; row 0 at the top), so that the
// front buffer goes to the X server as it is.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "framebuffer/framebuffer.h"

namespace glfixed {
class Context;
}

namespace glfixed::platform {

// Puts a surface's front buffer on the screen, and tells the size of the
// window it stands for.
class Presenter {
 public:
  virtual ~Presenter() = default;
  virtual void present(const ColorBuffer& front) = 0;
  // False if the size cannot be known (the window is gone).
  virtual bool windowSize(int* width, int* height) = 0;
  // The connection is closing (XCloseDisplay's hooks run): send nothing
  // more, not even from the destructor.
  virtual void connectionClosing() {}
};

class Surface : public SurfaceHooks {
 public:
  // `alphaBits` 0 or 8. The buffers start black (and alpha 0).
  Surface(int width, int height, bool doubleBuffered, int alphaBits, std::unique_ptr<Presenter> presenter);
  ~Surface() override;
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  bool doubleBuffered() const { return doubleBuffered_; }
  bool isWindow() const { return presenter_ != nullptr; }

  ColorBuffer frontView() const { return view(front_); }
  ColorBuffer backView() const { return doubleBuffered_ ? view(back_) : ColorBuffer{}; }

  // glXSwapBuffers, eglSwapBuffers: the back buffer becomes the front one and
  // reaches the screen; then the window's size is looked at again, as Mesa's
  // drisw does after a swap. Single-buffered: the front buffer is presented.
  void swapBuffers();
  // Presents the front buffer (glXWaitGL, a flush of front-buffer drawing).
  void presentFront();
  // Reallocates the buffers to the window's current size if it changed.
  void checkWindowSize();
  // The presenter's connection is closing: nothing is presented after.
  void connectionClosing() {
    if (presenter_) presenter_->connectionClosing();
  }

  // The contexts whose framebuffer points into this surface, so that a resize
  // can point them at the new buffers (platform/surface.cpp: makeCurrent).
  void attach(Context* ctx);
  void detach(Context* ctx);

  // SurfaceHooks.
  void frontBufferFlushed() override { presentFront(); }
  void viewportChanged() override { checkWindowSize(); }

 private:
  ColorBuffer view(const std::vector<uint8_t>& pixels) const;
  void resize(int width, int height);
  void rebindAttached();  // with mutex_ held: the attached contexts' views again

  int width_, height_;
  bool doubleBuffered_;
  int alphaBits_;
  std::vector<uint8_t> front_, back_;
  std::unique_ptr<Presenter> presenter_;
  std::mutex mutex_;  // guards attached_
  std::vector<Context*> attached_;
};

// Binds `draw` and `read` (null: surfaceless, no default framebuffer) to
// `ctx`'s framebuffer, and the context to this thread (ctx null: the
// thread's current context is released; its buffered vertices are drawn
// first). At a context's first surface the viewport and scissor box take the
// surface's size (GL 2.1 §2.11.1, §4.1.2) and the draw and read buffers
// start as GL_BACK on a double-buffered surface, GL_FRONT otherwise (§4.2.1).
// The caller keeps both surfaces alive while they are bound.
void makeCurrent(Context* ctx, Surface* draw, Surface* read);

// Points `ctx`'s framebuffer at its surfaces' buffers again (after a resize).
void bindSurfaces(Context& ctx, Surface* draw, Surface* read);

}  // namespace glfixed::platform
