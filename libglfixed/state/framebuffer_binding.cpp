#include "state/framebuffer_binding.h"

#include <utility>

namespace glfixed {

using namespace fbo_enums;

FramebufferObject* drawFramebufferObject(Context& ctx) {
  return ctx.fbo.draw ? ctx.framebufferObjects->findFramebuffer(ctx.fbo.draw) : nullptr;
}

FramebufferObject* readFramebufferObject(Context& ctx) {
  return ctx.fbo.read ? ctx.framebufferObjects->findFramebuffer(ctx.fbo.read) : nullptr;
}

void bindFramebuffers(Context& ctx, GLuint draw, GLuint read) {
  const bool wasBound = ctx.objectBound();
  // The window's draw and read buffers step aside for an object's (each
  // framebuffer has its own, GL 3.0 §4.2.1), and come back with the window.
  if (ctx.fbo.draw == 0 && draw != 0) ctx.fbo.windowDrawBuffer = ctx.colorBuffer.drawBuffer;
  if (ctx.fbo.draw != 0 && draw == 0) ctx.colorBuffer.drawBuffer = ctx.fbo.windowDrawBuffer;
  if (ctx.fbo.read == 0 && read != 0) ctx.fbo.windowReadBuffer = ctx.pixelMode.readBuffer;
  if (ctx.fbo.read != 0 && read == 0) ctx.pixelMode.readBuffer = ctx.fbo.windowReadBuffer;
  ctx.fbo.draw = draw;
  ctx.fbo.read = read;
  if (FramebufferObject* d = drawFramebufferObject(ctx)) ctx.colorBuffer.drawBuffer = d->drawBuffers[0];
  if (FramebufferObject* r = readFramebufferObject(ctx)) ctx.pixelMode.readBuffer = r->readBuffer;
  const bool nowBound = ctx.objectBound();
  if (!wasBound && nowBound) {
    ctx.parkedWindow = std::move(ctx.framebuffer);
    ctx.framebuffer = Framebuffer{};
  } else if (wasBound && !nowBound) {
    ctx.framebuffer = std::move(ctx.parkedWindow);
    ctx.parkedWindow = Framebuffer{};
  }
  ctx.selectWindowBuffers();
  refreshFramebuffer(ctx);
}

namespace {

// The view of the buffer an object's draw or read buffer names.
ColorBuffer attachmentNamed(Context& ctx, FramebufferObject& fb, GLenum buffer) {
  ColorBuffer c;
  if (buffer >= kColorAttachment0 && buffer < kColorAttachment0 + kMaxColorAttachments)
    colorView(fb.color[buffer - kColorAttachment0], *ctx.framebufferObjects, *ctx.textures, &c);
  return c;
}

}  // namespace

void refreshFramebuffer(Context& ctx) {
  if (!ctx.objectBound()) {
    ctx.fbo.drawStatus = ctx.fbo.readStatus = kComplete;
    return;
  }
  Framebuffer& win = ctx.parkedWindow;
  Framebuffer& fb = ctx.framebuffer;
  FramebufferObjects& objects = *ctx.framebufferObjects;
  win.selectBuffers(ctx.windowDrawBuffer(), ctx.windowReadBuffer());
  Framebuffer composed;
  // Draw side.
  if (FramebufferObject* d = drawFramebufferObject(ctx)) {
    int w = 0, h = 0;
    ctx.fbo.drawStatus = framebufferStatus(*d, objects, *ctx.textures, &w, &h);
    if (ctx.fbo.drawStatus == kComplete) {
      composed.object = true;
      composed.objectWidth = w;
      composed.objectHeight = h;
      composed.color = attachmentNamed(ctx, *d, ctx.colorBuffer.drawBuffer);
      composed.front = composed.color;
      for (int i = 1; i < kMaxColorAttachments; ++i) {
        const ColorBuffer c = attachmentNamed(ctx, *d, d->drawBuffers[i]);
        if (!c.pixels) continue;
        if (!composed.color.pixels)
          composed.color = composed.front = c;
        else
          composed.moreColor[composed.moreColorCount++] = c;
      }
      depthView(*d, objects, *ctx.textures, &composed.depth);
    }
  } else {
    ctx.fbo.drawStatus = kComplete;
    composed.front = win.front;
    composed.back = win.back;
    composed.color = win.color;
    composed.surface = win.surface;
    composed.depth.viewOf(win.depth);
  }
  // Read side.
  if (FramebufferObject* r = readFramebufferObject(ctx)) {
    int w = 0, h = 0;
    ctx.fbo.readStatus = framebufferStatus(*r, objects, *ctx.textures, &w, &h);
    if (ctx.fbo.readStatus == kComplete) {
      composed.read = attachmentNamed(ctx, *r, ctx.pixelMode.readBuffer);
      composed.readFront = composed.read;
    }
  } else {
    ctx.fbo.readStatus = kComplete;
    composed.readFront = win.readFront;
    composed.readBack = win.readBack;
    composed.read = win.read;
    composed.readSurface = win.readSurface;
  }
  fb = std::move(composed);
}

bool drawFramebufferComplete(Context& ctx) {
  refreshFramebuffer(ctx);
  if (ctx.fbo.drawStatus == kComplete) return true;
  ctx.recordError(kInvalidFramebufferOperation);
  return false;
}

bool readFramebufferComplete(Context& ctx) {
  refreshFramebuffer(ctx);
  if (ctx.fbo.readStatus == kComplete) return true;
  ctx.recordError(kInvalidFramebufferOperation);
  return false;
}

}  // namespace glfixed
