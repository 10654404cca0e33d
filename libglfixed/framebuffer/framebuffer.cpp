#include "framebuffer/framebuffer.h"

#include <algorithm>
#include <cmath>

namespace glfixed {

void ColorBuffer::setFormat(PixelFormat f) {
  format = f;
  switch (f) {
    case PixelFormat::kRGBA: bytesPerPixel = 4; red = 0; green = 1; blue = 2; alpha = 3; break;
    case PixelFormat::kBGRA: bytesPerPixel = 4; red = 2; green = 1; blue = 0; alpha = 3; break;
    case PixelFormat::kARGB: bytesPerPixel = 4; red = 1; green = 2; blue = 3; alpha = 0; break;
    case PixelFormat::kRGB:  bytesPerPixel = 3; red = 0; green = 1; blue = 2; alpha = -1; break;
    case PixelFormat::kBGR:  bytesPerPixel = 3; red = 2; green = 1; blue = 0; alpha = -1; break;
    case PixelFormat::kBGRX: bytesPerPixel = 4; red = 2; green = 1; blue = 0; alpha = -1; break;
    case PixelFormat::kRGBX: bytesPerPixel = 4; red = 0; green = 1; blue = 2; alpha = -1; break;
  }
}

Framebuffer::Buffers Framebuffer::buffersNamed(GLenum buffer, bool forReading) const {
  const bool twoBuffers = forReading ? readBack.pixels != nullptr : doubleBuffered();
  const Buffers back = twoBuffers ? Buffers::kBack : Buffers::kFront;
  switch (buffer) {
    case GL_NONE: return Buffers::kNone;
    case GL_FRONT: case GL_FRONT_LEFT: return Buffers::kFront;
    case GL_BACK: case GL_BACK_LEFT: return back;
    case GL_LEFT: case GL_FRONT_AND_BACK:
      return forReading || !twoBuffers ? Buffers::kFront : Buffers::kBoth;
    case GL_RIGHT: case GL_FRONT_RIGHT: case GL_BACK_RIGHT: case GL_AUX0: case GL_AUX1: case GL_AUX2: case GL_AUX3:
      return Buffers::kMissing;
    default:
      // GL_COLOR_ATTACHMENT0..31 (0x8CE0..) name no buffer of a window-system framebuffer.
      return buffer >= 0x8CE0 && buffer <= 0x8CE0 + 31 ? Buffers::kMissing
                                                                                 : Buffers::kUnknown;
  }
}

void Framebuffer::selectBuffers(GLenum drawBuffer, GLenum readBuffer) {
  const auto view = [](Buffers b, const ColorBuffer& f, const ColorBuffer& bk) {
    switch (b) {
      case Buffers::kFront: return f;
      case Buffers::kBack: case Buffers::kBoth: return bk;
      default: return ColorBuffer{};  // GL_NONE: nothing is drawn or read
    }
  };
  color = view(buffersNamed(drawBuffer, false), front, back);
  read = view(buffersNamed(readBuffer, true), readFront, readBack);
}

DepthBuffer& DepthBuffer::operator=(const DepthBuffer& o) {
  if (this == &o) return *this;
  bits_ = o.bits_;
  stencilBits_ = o.stencilBits_;
  width_ = o.width_;
  height_ = o.height_;
  isView_ = o.isView_;
  if (isView_) {
    own16_.clear();
    own32_.clear();
    own8_.clear();
    d16_ = o.d16_;
    d32_ = o.d32_;
    s8_ = o.s8_;
  } else {
    own16_ = o.own16_;
    own32_ = o.own32_;
    own8_ = o.own8_;
    pointAtOwnStorage();
  }
  return *this;
}

DepthBuffer& DepthBuffer::operator=(DepthBuffer&& o) noexcept {
  if (this == &o) return *this;
  bits_ = o.bits_;
  stencilBits_ = o.stencilBits_;
  width_ = o.width_;
  height_ = o.height_;
  isView_ = o.isView_;
  own16_ = std::move(o.own16_);
  own32_ = std::move(o.own32_);
  own8_ = std::move(o.own8_);
  if (isView_) {
    d16_ = o.d16_;
    d32_ = o.d32_;
    s8_ = o.s8_;
  } else {
    pointAtOwnStorage();  // a moved vector keeps its memory
  }
  o.pointAtOwnStorage();
  return *this;
}

void DepthBuffer::pointAtOwnStorage() {
  d16_ = own16_.empty() ? nullptr : own16_.data();
  d32_ = own32_.empty() ? nullptr : own32_.data();
  s8_ = own8_.empty() ? nullptr : own8_.data();
}

void DepthBuffer::resize(int width, int height, int bits, int stencilBits) {
  bits_ = bits;
  stencilBits_ = stencilBits > 0 ? 8 : 0;
  width_ = width;
  height_ = height;
  isView_ = false;
  size_t n = static_cast<size_t>(width) * height;
  own16_.assign(bits == 16 ? n : 0, 0);
  own32_.assign(bits == 24 ? n : 0, 0);
  own8_.assign(stencilBits_ && bits == 0 ? n : 0, 0);
  pointAtOwnStorage();
}

void DepthBuffer::view(int width, int height, int bits, int stencilBits, void* depth, uint8_t* stencil8) {
  own16_.clear();
  own32_.clear();
  own8_.clear();
  bits_ = bits;
  stencilBits_ = stencilBits > 0 ? 8 : 0;
  width_ = width;
  height_ = height;
  isView_ = true;
  d16_ = bits == 16 ? static_cast<uint16_t*>(depth) : nullptr;
  d32_ = bits == 24 ? static_cast<uint32_t*>(depth) : nullptr;
  s8_ = stencilBits_ && bits == 0 ? stencil8 : nullptr;
}

std::vector<uint8_t> DepthBuffer::saveValues() const {
  const size_t n = count();
  std::vector<uint8_t> out;
  const uint8_t* d = bits_ == 16 ? reinterpret_cast<const uint8_t*>(d16_) : reinterpret_cast<const uint8_t*>(d32_);
  if (d) out.insert(out.end(), d, d + n * static_cast<size_t>(bytesPerValue()));
  if (s8_) out.insert(out.end(), s8_, s8_ + n);
  return out;
}

void DepthBuffer::restoreValues(const std::vector<uint8_t>& saved) {
  const size_t n = count();
  size_t at = 0;
  uint8_t* d = bits_ == 16 ? reinterpret_cast<uint8_t*>(d16_) : reinterpret_cast<uint8_t*>(d32_);
  if (d) {
    const size_t bytes = n * static_cast<size_t>(bytesPerValue());
    if (saved.size() < bytes) return;
    std::copy(saved.begin(), saved.begin() + static_cast<std::ptrdiff_t>(bytes), d);
    at = bytes;
  }
  if (s8_ && saved.size() >= at + n)
    std::copy(saved.begin() + static_cast<std::ptrdiff_t>(at), saved.begin() + static_cast<std::ptrdiff_t>(at + n),
              s8_);
}

void DepthBuffer::fill(uint32_t v) {
  const size_t n = count();
  if (bits_ == 0) return;
  if (bits_ == 16)
    std::fill(d16_, d16_ + n, static_cast<uint16_t>(v));
  else if (!packedStencil())
    std::fill(d32_, d32_ + n, v);
  else
    for (size_t i = 0; i < n; ++i) d32_[i] = (d32_[i] & 0xff000000u) | (v & 0xffffffu);
}

void DepthBuffer::fillStencil(uint32_t v, uint32_t writeMask) {
  writeMask &= 0xffu;
  v &= writeMask;
  const size_t n = count();
  if (stencilBits_ == 0) return;
  if (packedStencil()) {
    const uint32_t keep = ~(writeMask << 24);
    for (size_t i = 0; i < n; ++i) d32_[i] = (d32_[i] & keep) | (v << 24);
  } else {
    for (size_t i = 0; i < n; ++i) s8_[i] = static_cast<uint8_t>((s8_[i] & ~writeMask) | v);
  }
}

uint8_t floatToUnorm8(float v) {
  v = std::min(std::max(v, 0.0f), 1.0f);
  return static_cast<uint8_t>(std::nearbyint(v * 255.0f));
}

uint32_t depthToUnorm(double z, int bits) {
  z = std::min(std::max(z, 0.0), 1.0);
  double maxv = bits == 16 ? 65535.0 : 16777215.0;
  return static_cast<uint32_t>(std::nearbyint(z * maxv));
}

}  // namespace glfixed
