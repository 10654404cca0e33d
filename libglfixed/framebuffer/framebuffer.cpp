#include "framebuffer/framebuffer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace glfixed {

void ColorBuffer::setFormat(PixelFormat f) {
  format = f;
  channels = ChannelType::kUnorm8;
  switch (f) {
    case PixelFormat::kRGBA: bytesPerPixel = 4; red = 0; green = 1; blue = 2; alpha = 3; break;
    case PixelFormat::kBGRA: bytesPerPixel = 4; red = 2; green = 1; blue = 0; alpha = 3; break;
    case PixelFormat::kARGB: bytesPerPixel = 4; red = 1; green = 2; blue = 3; alpha = 0; break;
    case PixelFormat::kRGB:  bytesPerPixel = 3; red = 0; green = 1; blue = 2; alpha = -1; break;
    case PixelFormat::kBGR:  bytesPerPixel = 3; red = 2; green = 1; blue = 0; alpha = -1; break;
    case PixelFormat::kBGRX: bytesPerPixel = 4; red = 2; green = 1; blue = 0; alpha = -1; break;
    case PixelFormat::kRGBX: bytesPerPixel = 4; red = 0; green = 1; blue = 2; alpha = -1; break;
    // clang-format off
    case PixelFormat::kRGB565:   bytesPerPixel = 2;  red = 0; green = 1; blue = 2; alpha = -1; channels = ChannelType::kRGB565; break;
    case PixelFormat::kRGBA16:   bytesPerPixel = 8;  red = 0; green = 1; blue = 2; alpha = 3;  channels = ChannelType::kUnorm16; break;
    case PixelFormat::kRGB16:    bytesPerPixel = 6;  red = 0; green = 1; blue = 2; alpha = -1; channels = ChannelType::kUnorm16; break;
    case PixelFormat::kRGBA32F:  bytesPerPixel = 16; red = 0; green = 1; blue = 2; alpha = 3;  channels = ChannelType::kFloat32; break;
    case PixelFormat::kRGB32F:   bytesPerPixel = 12; red = 0; green = 1; blue = 2; alpha = -1; channels = ChannelType::kFloat32; break;
    // clang-format on
  }
}

// The object formats' layout: R, G, B and (when there is one) A in that
// order, each channel in `bytesPerPixel / 4` bytes.
void ColorBuffer::setRgbaLayout(ChannelType type, int pixelBytes, bool withAlpha) {
  format = PixelFormat::kRGBA;
  channels = type;
  bytesPerPixel = pixelBytes;
  red = 0;
  green = 1;
  blue = 2;
  alpha = withAlpha ? 3 : -1;
}

void ColorBuffer::setUnormBits(int r, int g, int b, int a) {
  setRgbaLayout(ChannelType::kUnormBits, 4, a > 0);
  const int v[4] = {r, g, b, a};
  for (int k = 0; k < 4; ++k) bits[k] = static_cast<uint8_t>(v[k]);
}

void ColorBuffer::setUnormWideBits(int r, int g, int b, int a) {
  setRgbaLayout(ChannelType::kUnormWideBits, 8, a > 0);
  const int v[4] = {r, g, b, a};
  for (int k = 0; k < 4; ++k) bits[k] = static_cast<uint8_t>(v[k]);
}

void ColorBuffer::setHalfFloat(bool withAlpha) { setRgbaLayout(ChannelType::kFloat16, 8, withAlpha); }

uint16_t floatToHalf(float v) {
  uint32_t b;
  std::memcpy(&b, &v, 4);
  const uint16_t sign = static_cast<uint16_t>((b >> 16) & 0x8000u);
  const uint32_t a = b & 0x7fffffffu;
  if (a > 0x7f800000u) return static_cast<uint16_t>(sign | 0x7e00u);  // NaN
  if (a >= 0x47800000u) return static_cast<uint16_t>(sign | 0x7bffu);  // >= 65536: the largest half
  if (a >= 0x38800000u)  // normal halves: the exponent rebiased, the mantissa's top 10 bits
    return static_cast<uint16_t>(sign | (((a >> 23) - 112u) << 10) | ((a >> 13) & 0x3ffu));
  // Denormal halves: units of 2^-24, truncated (exact scaling by a power of two).
  float mag;
  std::memcpy(&mag, &a, 4);
  return static_cast<uint16_t>(sign | static_cast<uint32_t>(mag * 16777216.0f));
}

float halfToFloat(uint16_t h) {
  const uint32_t sign = static_cast<uint32_t>(h & 0x8000u) << 16;
  const uint32_t e = (h >> 10) & 31u, m = h & 0x3ffu;
  if (e == 0) {
    const float mag = static_cast<float>(m) * (1.0f / 16777216.0f);
    return sign ? -mag : mag;
  }
  const uint32_t b = sign | (e == 31 ? (0xffu << 23) | (m << 13) : ((e + 112u) << 23) | (m << 13));
  float v;
  std::memcpy(&v, &b, 4);
  return v;
}

void ColorBuffer::setChannels(ChannelType type, int bpp, int r, int g, int b, int a) {
  format = PixelFormat::kRGBA;
  channels = type;
  bytesPerPixel = bpp;
  red = r;
  green = g;
  blue = b;
  alpha = a;
}

int ColorBuffer::channelBits(int k) const {
  const int offset[4] = {red, green, blue, alpha};
  if (offset[k] < 0 || (luminance && k < 3)) return 0;
  switch (channels) {
    case ChannelType::kUnormBits:
    case ChannelType::kUnormWideBits: return bits[k];
    case ChannelType::kUnorm8: return 8;
    case ChannelType::kRGB565: return k == 1 ? 6 : 5;
    case ChannelType::kUnorm16:
    case ChannelType::kFloat16: return 16;
    case ChannelType::kFloat32: return 32;
  }
  return 8;
}

namespace {

// The 5-6-5 word's channels (red in the top bits) and their maxima.
constexpr int kShift565[3] = {11, 5, 0};
constexpr uint32_t kMax565[3] = {31, 63, 31};

uint16_t load16(const uint8_t* p) {
  uint16_t v;
  std::memcpy(&v, p, 2);
  return v;
}
void store16(uint8_t* p, uint16_t v) { std::memcpy(p, &v, 2); }

// NaN gives 0.
float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

}  // namespace

void ColorBuffer::writeConverted(int x, int y, const uint8_t rgba[4]) const {
  uint8_t* p = pixel(x, y);
  if (channels == ChannelType::kUnormBits) {
    const int offset[4] = {red, green, blue, alpha};
    for (int k = 0; k < 4; ++k)
      if (offset[k] >= 0) p[offset[k]] = byteToUnormBits(rgba[k], bits[k]);
    return;
  }
  if (channels == ChannelType::kRGB565) {
    // llvmpipe's 8-bit path keeps the top bits of each byte.
    store16(p, static_cast<uint16_t>(((rgba[0] >> 3) << 11) | ((rgba[1] >> 2) << 5) | (rgba[2] >> 3)));
    return;
  }
  const float f[4] = {rgba[0] * (1.0f / 255.0f), rgba[1] * (1.0f / 255.0f), rgba[2] * (1.0f / 255.0f),
                      rgba[3] * (1.0f / 255.0f)};
  writeFloat(x, y, f);
}

void ColorBuffer::readConverted(int x, int y, uint8_t rgba[4]) const {
  if (channels == ChannelType::kUnormBits) {
    const uint8_t* p = pixel(x, y);
    const int offset[4] = {red, green, blue, alpha};
    for (int k = 0; k < 4; ++k) rgba[k] = offset[k] >= 0 ? unormBitsToByte(p[offset[k]], bits[k]) : k == 3 ? 255 : 0;
    return;
  }
  if (channels == ChannelType::kRGB565) {
    // Bit replication: the same bytes as rint(v * 255 / max).
    const uint16_t w = load16(pixel(x, y));
    const uint32_t r = w >> 11, g = (w >> 5) & 63, b = w & 31;
    rgba[0] = static_cast<uint8_t>((r << 3) | (r >> 2));
    rgba[1] = static_cast<uint8_t>((g << 2) | (g >> 4));
    rgba[2] = static_cast<uint8_t>((b << 3) | (b >> 2));
    rgba[3] = 255;
    return;
  }
  float f[4];
  readFloat(x, y, f);
  for (int k = 0; k < 4; ++k) rgba[k] = floatToUnorm8(f[k]);
}

void ColorBuffer::readFloat(int x, int y, float rgba[4]) const {
  // A channel not stored: colour 0, alpha 1.
  const auto missing = [](int k) { return k == 3 ? 1.0f : 0.0f; };
  const uint8_t* p = pixel(x, y);
  const int offset[4] = {red, green, blue, alpha};
  switch (channels) {
    case ChannelType::kUnorm8:
      for (int k = 0; k < 4; ++k) rgba[k] = offset[k] >= 0 ? p[offset[k]] * (1.0f / 255.0f) : missing(k);
      return;
    case ChannelType::kRGB565: {
      const uint16_t w = load16(p);
      for (int k = 0; k < 3; ++k)
        rgba[k] =
            static_cast<float>((w >> kShift565[k]) & kMax565[k]) * (1.0f / static_cast<float>(kMax565[k]));
      rgba[3] = 1.0f;
      return;
    }
    case ChannelType::kUnormBits:
      for (int k = 0; k < 4; ++k) {
        const float max = static_cast<float>((1u << bits[k]) - 1u);
        rgba[k] = offset[k] >= 0 ? static_cast<float>(p[offset[k]]) * (1.0f / max) : missing(k);
      }
      return;
    case ChannelType::kUnorm16:
      for (int k = 0; k < 4; ++k)
        rgba[k] = offset[k] >= 0 ? static_cast<float>(load16(p + 2 * offset[k])) * (1.0f / 65535.0f) : missing(k);
      return;
    case ChannelType::kUnormWideBits:
      // v times the float nearest 1 / max, as Mesa unpacks them (probed on
      // 10 bits: v / max in float differs on 79 of 4096 values).
      for (int k = 0; k < 4; ++k) {
        const float scale = 1.0f / static_cast<float>((1u << bits[k]) - 1u);
        rgba[k] = offset[k] >= 0 ? static_cast<float>(load16(p + 2 * offset[k])) * scale : missing(k);
      }
      return;
    case ChannelType::kFloat16:
      for (int k = 0; k < 4; ++k) rgba[k] = offset[k] >= 0 ? halfToFloat(load16(p + 2 * offset[k])) : 1.0f;
      return;
    case ChannelType::kFloat32:
      for (int k = 0; k < 4; ++k) {
        rgba[k] = 1.0f;
        if (offset[k] >= 0) std::memcpy(&rgba[k], p + 4 * offset[k], 4);
      }
      return;
  }
}

void ColorBuffer::writeFloat(int x, int y, const float rgba[4], const bool* mask, bool halfUp) const {
  uint8_t* p = pixel(x, y);
  // A clamped channel as an unsigned value of at most `max`.
  const auto quantize = [halfUp](float v, float max) -> uint32_t {
    const float scaled = clamp01(v) * max;
    return static_cast<uint32_t>(halfUp ? std::floor(scaled + 0.5f) : std::nearbyint(scaled));
  };
  const int offset[4] = {red, green, blue, alpha};
  switch (channels) {
    case ChannelType::kUnorm8:
      for (int k = 0; k < 4; ++k)
        if (offset[k] >= 0 && (!mask || mask[k])) p[offset[k]] = floatToUnorm8(rgba[k]);
      return;
    case ChannelType::kRGB565: {
      uint32_t w = load16(p);
      for (int k = 0; k < 3; ++k) {
        if (mask && !mask[k]) continue;
        const uint32_t v = quantize(rgba[k], static_cast<float>(kMax565[k]));
        w = (w & ~(kMax565[k] << kShift565[k])) | (v << kShift565[k]);
      }
      store16(p, static_cast<uint16_t>(w));
      return;
    }
    case ChannelType::kUnormBits:
      for (int k = 0; k < 4; ++k)
        if (offset[k] >= 0 && (!mask || mask[k]))
          p[offset[k]] = static_cast<uint8_t>(quantize(rgba[k], static_cast<float>((1u << bits[k]) - 1u)));
      return;
    case ChannelType::kUnorm16:
      for (int k = 0; k < 4; ++k)
        if (offset[k] >= 0 && (!mask || mask[k]))
          store16(p + 2 * offset[k], static_cast<uint16_t>(quantize(rgba[k], 65535.0f)));
      return;
    case ChannelType::kUnormWideBits:
      // A clear rounds from float; anything else is stored as llvmpipe
      // stores a fragment, through its 16-bit type (unorm16ToBits).
      for (int k = 0; k < 4; ++k)
        if (offset[k] >= 0 && (!mask || mask[k]))
          store16(p + 2 * offset[k],
                  static_cast<uint16_t>(halfUp ? quantize(rgba[k], static_cast<float>((1u << bits[k]) - 1u))
                                               : unorm16ToBits(quantize(rgba[k], 65535.0f), bits[k])));
      return;
    case ChannelType::kFloat16:
      for (int k = 0; k < 4; ++k)
        if (offset[k] >= 0 && (!mask || mask[k])) store16(p + 2 * offset[k], floatToHalf(rgba[k]));
      return;
    case ChannelType::kFloat32:
      for (int k = 0; k < 4; ++k)
        if (offset[k] >= 0 && (!mask || mask[k])) std::memcpy(p + 4 * offset[k], &rgba[k], 4);
      return;
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
  depthless_ = o.depthless_;
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
  depthless_ = o.depthless_;
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
  depthless_ = false;
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
  depthless_ = false;
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
