#include "framebuffer/accum_buffer.h"

#include <xmmintrin.h>

#include <cmath>

#include "framebuffer/framebuffer.h"
#include "framebuffer/read_pixels.h"

namespace glfixed {

namespace {

// (GLshort)(float) as GCC compiles it on x86-64: cvttss2si to 32 bits
// (out of range or NaN: INT32_MIN), then the low 16 bits.
int16_t truncToShort(float v) {
  return static_cast<int16_t>(static_cast<uint16_t>(_mm_cvtt_ss2si(_mm_set_ss(v))));
}
int16_t wrapToShort(int32_t v) {
  return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(v)));
}

// Mesa's FLOAT_TO_SHORT for the clear value: ((int)(65535 * x) - 1) / 2.
int16_t clearShort(float x) {
  const int32_t i = _mm_cvtt_ss2si(_mm_set_ss(65535.0f * x));
  return wrapToShort(static_cast<int32_t>((static_cast<int64_t>(i) - 1) / 2));
}

// Mesa's unpack of an 8-bit unorm channel: x * (1 / 255).
float unormToFloat(uint8_t x) { return static_cast<float>(x) * (1.0f / 255.0f); }

// Mesa's _mesa_float_to_unorm(x, 8): negative 0, past 1 255, else x * 255
// rounded to nearest even (lrintf: NaN gives LONG_MIN, whose low byte is 0).
uint8_t floatToUnorm(float x) {
  if (x < 0.0f) return 0;
  if (x > 1.0f) return 255;
  return static_cast<uint8_t>(static_cast<unsigned long>(std::lrint(x * 255.0f)));
}

}  // namespace

void AccumBuffer::resize(int width, int height, bool present) {
  present_ = present;
  width_ = present ? width : 0;
  height_ = present ? height : 0;
  values_.assign(present ? static_cast<size_t>(width) * height * 4 : 0, 0);
}

void AccumBuffer::clear(const PixelBox& box, const float value[4]) {
  if (!present_) return;
  const int16_t v[4] = {clearShort(value[0]), clearShort(value[1]), clearShort(value[2]),
                        clearShort(value[3])};
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x)
      for (int k = 0; k < 4; ++k) values_[index(x, y) + k] = v[k];
}

void AccumBuffer::accumulate(const ColorBuffer& src, const PixelBox& box, float value, bool load) {
  if (!present_ || !src.pixels) return;
  const float scale = value * 32767.0f;
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x) {
      float f[4];
      if (src.channels == ChannelType::kUnorm8) {
        uint8_t rgba[4];
        src.read(x, y, rgba);
        for (int k = 0; k < 4; ++k) f[k] = unormToFloat(rgba[k]);
      } else {
        src.readFloat(x, y, f);  // Mesa unpacks any buffer to floats
      }
      int16_t* acc = &values_[index(x, y)];
      for (int k = 0; k < 4; ++k) {
        const int16_t c = truncToShort(f[k] * scale);
        acc[k] = load ? c : wrapToShort(int32_t{acc[k]} + c);
      }
    }
}

void AccumBuffer::scaleOrBias(const PixelBox& box, float value, bool bias) {
  if (!present_) return;
  const int16_t incr = truncToShort(value * 32767.0f);
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x) {
      int16_t* acc = &values_[index(x, y)];
      for (int k = 0; k < 4; ++k)
        acc[k] =
            bias ? wrapToShort(int32_t{acc[k]} + incr) : truncToShort(static_cast<float>(acc[k]) * value);
    }
}

void AccumBuffer::returnTo(const ColorBuffer& dst, const PixelBox& box, float value,
                           const bool writeMask[4]) const {
  if (!present_ || !dst.pixels) return;
  const float scale = value / 32767.0f;
  const int offset[4] = {dst.red, dst.green, dst.blue, dst.alpha};
  if (dst.channels != ChannelType::kUnorm8) {
    // 5-6-5, 16-bit and float buffers: the clamped float, in the buffer's precision.
    for (int y = box.y0; y < box.y1; ++y)
      for (int x = box.x0; x < box.x1; ++x) {
        const int16_t* acc = &values_[index(x, y)];
        float f[4];
        for (int k = 0; k < 4; ++k) {
          const float v = static_cast<float>(acc[k]) * scale;
          f[k] = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
        }
        dst.writeFloat(x, y, f, writeMask);
      }
    return;
  }
  for (int y = box.y0; y < box.y1; ++y)
    for (int x = box.x0; x < box.x1; ++x) {
      const int16_t* acc = &values_[index(x, y)];
      uint8_t* p = dst.pixel(x, y);
      for (int k = 0; k < 4; ++k)
        if (writeMask[k] && offset[k] >= 0) p[offset[k]] = floatToUnorm(static_cast<float>(acc[k]) * scale);
    }
}

}  // namespace glfixed
