#include "platform/x11_present.h"

#include "platform/x11_error_trap.h"

#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstdio>
#include <cstring>
#include <mutex>

namespace glfixed::platform {

namespace {

class X11Presenter : public Presenter {
 public:
  X11Presenter(Display* display, Drawable drawable, Visual* visual, int depth)
      : display_(display), drawable_(drawable), visual_(visual), depth_(depth) {
    gc_ = XCreateGC(display_, drawable_, 0, nullptr);
    useShm_ = XShmQueryExtension(display_);
  }
  ~X11Presenter() override {
    if (closing_) return;
    releaseShm();
    XFreeGC(display_, gc_);
  }

  // Inside XCloseDisplay, libXext may have forgotten MIT-SHM already: an
  // XShmDetach now would set it up again on a dying Display (and a later
  // Display at the same address would find it). The server frees the
  // segment with the connection; core requests (XFreeGC) are still fine.
  void connectionClosing() override {
    if (closing_) return;
    if (shmInfo_.shmaddr) shmdt(shmInfo_.shmaddr);
    shmInfo_.shmaddr = nullptr;
    if (shmImage_) {
      shmImage_->data = nullptr;
      XDestroyImage(shmImage_);  // client memory only
      shmImage_ = nullptr;
    }
    XFreeGC(display_, gc_);
    closing_ = gone_ = true;
  }

  // Under the error trap: a window destroyed under the context (the
  // program's, or at exit) must not reach the program's error handler.
  // After one failure the drawable is taken as gone: nothing more is sent
  // to it, and its size is no longer asked.
  void present(const ColorBuffer& front) override {
    if (!front.pixels || gone_) return;
    ErrorTrap trap(display_);
    if (!(useShm_ && presentShm(front))) {
      XImage* image = XCreateImage(display_, visual_, depth_, ZPixmap, 0, reinterpret_cast<char*>(front.pixels),
                                   front.width, front.height, 32, front.rowLength * 4);
      if (!image) return;
      image->byte_order = LSBFirst;  // the buffers' B, G, R, X bytes
      XPutImage(display_, drawable_, gc_, image, 0, 0, 0, 0, front.width, front.height);
      image->data = nullptr;  // the surface's memory, not Xlib's to free
      XDestroyImage(image);
    }
    if (trap.failed()) gone_ = true;
  }

  bool windowSize(int* width, int* height) override {
    int depth = 0;
    if (gone_) return false;
    return x11DrawableSize(display_, drawable_, width, height, &depth);
  }

 private:
  // The image lives in a shared segment the server reads; XSync waits until
  // it has, so the next frame may overwrite it.
  bool presentShm(const ColorBuffer& front) {
    if (!shmImage_ || shmImage_->width != front.width || shmImage_->height != front.height) {
      releaseShm();
      if (!attachShm(front.width, front.height)) {
        useShm_ = false;  // a remote server, or no segment: XPutImage from now on
        return false;
      }
    }
    for (int y = 0; y < front.height; ++y)
      std::memcpy(shmImage_->data + static_cast<size_t>(y) * shmImage_->bytes_per_line,
                  front.pixels + static_cast<size_t>(y) * front.rowLength * 4, static_cast<size_t>(front.width) * 4);
    XShmPutImage(display_, drawable_, gc_, shmImage_, 0, 0, 0, 0, front.width, front.height, False);
    XSync(display_, False);  // under present()'s error trap
    return true;
  }

  bool attachShm(int width, int height) {
    shmImage_ = XShmCreateImage(display_, visual_, depth_, ZPixmap, nullptr, &shmInfo_, width, height);
    if (!shmImage_) return false;
    if (shmImage_->bits_per_pixel != 32) return releaseShm(), false;
    shmInfo_.shmid = shmget(IPC_PRIVATE, static_cast<size_t>(shmImage_->bytes_per_line) * height, IPC_CREAT | 0600);
    if (shmInfo_.shmid < 0) return releaseShm(), false;
    shmInfo_.shmaddr = shmImage_->data = static_cast<char*>(shmat(shmInfo_.shmid, nullptr, 0));
    shmctl(shmInfo_.shmid, IPC_RMID, nullptr);  // gone once both sides detach
    if (shmInfo_.shmaddr == reinterpret_cast<char*>(-1)) {
      shmInfo_.shmaddr = nullptr;
      return releaseShm(), false;
    }
    shmInfo_.readOnly = True;
    ErrorTrap trap(display_);
    XShmAttach(display_, &shmInfo_);
    if (trap.failed()) return releaseShm(), false;
    attached_ = true;
    return true;
  }

  void releaseShm() {
    if (attached_) {
      XShmDetach(display_, &shmInfo_);
      XSync(display_, False);
      attached_ = false;
    }
    if (shmInfo_.shmaddr) shmdt(shmInfo_.shmaddr);
    shmInfo_.shmaddr = nullptr;
    if (shmImage_) {
      shmImage_->data = nullptr;
      XDestroyImage(shmImage_);
      shmImage_ = nullptr;
    }
  }

  Display* display_;
  Drawable drawable_;
  Visual* visual_;
  int depth_;
  GC gc_;
  bool useShm_ = false;
  XImage* shmImage_ = nullptr;
  XShmSegmentInfo shmInfo_{};
  bool attached_ = false;
  bool gone_ = false;  // the drawable was destroyed
  bool closing_ = false;  // the connection is closing
};

}  // namespace

bool x11DrawableSize(Display* display, Drawable drawable, int* width, int* height, int* depth) {
  Window root;
  int x, y;
  unsigned w = 0, h = 0, border, d = 0;
  ErrorTrap trap(display);
  const Status ok = XGetGeometry(display, drawable, &root, &x, &y, &w, &h, &border, &d);
  if (trap.failed() || !ok) return false;
  *width = static_cast<int>(w);
  *height = static_cast<int>(h);
  *depth = static_cast<int>(d);
  return true;
}

std::unique_ptr<Presenter> makeX11Presenter(Display* display, Drawable drawable, Visual* visual) {
  int width, height, depth;
  if (!display || !x11DrawableSize(display, drawable, &width, &height, &depth)) {
    std::fprintf(stderr, "libglfixed: 0x%lx is not an X11 drawable\n", static_cast<unsigned long>(drawable));
    return nullptr;
  }
  if (!visual) {
    XWindowAttributes attributes;
    ErrorTrap trap(display);
    const Status ok = XGetWindowAttributes(display, drawable, &attributes);
    if (trap.failed() || !ok) {
      std::fprintf(stderr, "libglfixed: 0x%lx is not an X11 window\n", static_cast<unsigned long>(drawable));
      return nullptr;
    }
    visual = attributes.visual;
  }
  if ((depth != 24 && depth != 32) || visual->c_class != TrueColor || visual->red_mask != 0xff0000 ||
      visual->green_mask != 0xff00 || visual->blue_mask != 0xff) {
    std::fprintf(stderr, "libglfixed: drawable 0x%lx: only depth-24 and depth-32 TrueColor visuals are supported\n",
                 static_cast<unsigned long>(drawable));
    return nullptr;
  }
  return std::make_unique<X11Presenter>(display, drawable, visual, depth);
}

}  // namespace glfixed::platform
