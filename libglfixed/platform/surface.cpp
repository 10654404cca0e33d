#include "platform/surface.h"

#include <algorithm>

#include "pipeline/immediate_mode.h"
#include "pipeline/pixel_rect.h"
#include "state/context.h"

namespace glfixed::platform {

Surface::Surface(int width, int height, bool doubleBuffered, int alphaBits, std::unique_ptr<Presenter> presenter)
    : width_(0), height_(0), doubleBuffered_(doubleBuffered), alphaBits_(alphaBits), presenter_(std::move(presenter)) {
  resize(width, height);
}

namespace {

// A context that lets go of its surfaces keeps its depth buffer (it gets the
// same size again when made current on the same window) but no pointer
// into a surface that may be gone by then.
void unbindSurfaces(Context& ctx) {
  Framebuffer& fb = ctx.windowFramebuffer();
  fb.surface = fb.readSurface = nullptr;
  fb.front = fb.back = fb.readFront = fb.readBack = fb.color = fb.read = ColorBuffer{};
}

}  // namespace

// Destroyed while still bound (the platform layer keeps current surfaces
// alive, so only by a program's error): the contexts draw nothing after.
Surface::~Surface() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (Context* ctx : attached_) unbindSurfaces(*ctx);
}

ColorBuffer Surface::view(const std::vector<uint8_t>& pixels) const {
  ColorBuffer c;
  c.setFormat(alphaBits_ > 0 ? PixelFormat::kBGRA : PixelFormat::kBGRX);
  c.pixels = const_cast<uint8_t*>(pixels.data());
  c.width = width_;
  c.height = height_;
  c.rowLength = width_;
  c.yUp = false;  // an X11 image: row 0 is the top row
  return c;
}

void Surface::resize(int width, int height) {
  width_ = std::clamp(width, 1, kMaxViewportSize);
  height_ = std::clamp(height, 1, kMaxViewportSize);
  const size_t bytes = static_cast<size_t>(width_) * height_ * 4;
  front_.assign(bytes, 0);
  back_.assign(doubleBuffered_ ? bytes : 0, 0);
}

void Surface::presentFront() {
  if (presenter_) presenter_->present(frontView());
}

void Surface::swapBuffers() {
  if (doubleBuffered_) front_.swap(back_);
  presentFront();
  if (doubleBuffered_) {
    // The views of the attached contexts follow the exchanged memory.
    std::lock_guard<std::mutex> lock(mutex_);
    rebindAttached();
  }
  checkWindowSize();
}

void Surface::rebindAttached() {
  for (Context* ctx : attached_)
    bindSurfaces(*ctx, dynamic_cast<Surface*>(ctx->windowFramebuffer().surface),
                 dynamic_cast<Surface*>(ctx->windowFramebuffer().readSurface));
}

void Surface::checkWindowSize() {
  int w = 0, h = 0;
  if (!presenter_ || !presenter_->windowSize(&w, &h)) return;
  if (w == width_ && h == height_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  for (Context* ctx : attached_) pipeline::flushVertices(*ctx);
  resize(w, h);
  rebindAttached();
}

void Surface::attach(Context* ctx) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (std::find(attached_.begin(), attached_.end(), ctx) == attached_.end()) attached_.push_back(ctx);
}

void Surface::detach(Context* ctx) {
  std::lock_guard<std::mutex> lock(mutex_);
  attached_.erase(std::remove(attached_.begin(), attached_.end(), ctx), attached_.end());
}

void bindSurfaces(Context& ctx, Surface* draw, Surface* read) {
  Framebuffer& fb = ctx.windowFramebuffer();
  fb.surface = draw;
  fb.readSurface = read;
  fb.front = draw ? draw->frontView() : ColorBuffer{};
  fb.back = draw ? draw->backView() : ColorBuffer{};
  fb.readFront = read ? read->frontView() : ColorBuffer{};
  fb.readBack = read ? read->backView() : ColorBuffer{};
  // The depth buffer is the context's, sized to the draw surface (a surface
  // shared by two contexts does not share its depth values).
  if (draw && (fb.depth.width() != draw->width() || fb.depth.height() != draw->height() ||
               fb.depth.bits() != ctx.requestedDepthBits || fb.depth.stencilBits() != ctx.requestedStencilBits))
    fb.depth.resize(draw->width(), draw->height(), ctx.requestedDepthBits, ctx.requestedStencilBits);
  // So is the accumulation buffer of a GLX configuration that has one.
  if (draw && (fb.accum.width() != draw->width() || fb.accum.height() != draw->height() ||
               fb.accum.present() != ctx.requestedAccum))
    fb.accum.resize(draw->width(), draw->height(), ctx.requestedAccum);
  ctx.selectWindowBuffers();
}

namespace {

void detachAll(Context& ctx) {
  if (auto* s = dynamic_cast<Surface*>(ctx.windowFramebuffer().surface)) s->detach(&ctx);
  if (auto* s = dynamic_cast<Surface*>(ctx.windowFramebuffer().readSurface)) s->detach(&ctx);
}

}  // namespace

void makeCurrent(Context* ctx, Surface* draw, Surface* read) {
  Context* previous = currentContext();
  if (previous) {
    pipeline::flushVertices(*previous);
    if (previous != ctx) pipeline::flushBitmapCache(*previous);  // _mesa_make_current flushes the old context
    // The previous context lets go of its surfaces (an OSMesa context has none).
    if (previous != ctx && (previous->windowFramebuffer().surface || previous->windowFramebuffer().readSurface)) {
      detachAll(*previous);
      unbindSurfaces(*previous);
    }
  }
  if (!ctx) return setCurrentContext(nullptr);
  detachAll(*ctx);
  if (draw) ctx->sizeToFirstSurface(draw->width(), draw->height(), draw->doubleBuffered());
  bindSurfaces(*ctx, draw, read);
  if (draw) draw->attach(ctx);
  if (read && read != draw) read->attach(ctx);
  setCurrentContext(ctx);
}

}  // namespace glfixed::platform
