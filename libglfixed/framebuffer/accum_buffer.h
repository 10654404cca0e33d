// The accumulation buffer (GL 2.1 §4.2.4) as Mesa keeps it: four signed
// 16-bit values a pixel (RGBA_SNORM16, GL_ACCUM_*_BITS 16 whatever the bits
// asked), 1.0 stored as 32767. Every operation is Mesa's software one
// (main/accum.c), in its arithmetic: products in single precision truncated
// to 16 bits as a C cast does on x86 (so sums past the range wrap around);
// reference/MESA_FACTS.md, "Accumulation buffer".
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glfixed {

struct ColorBuffer;  // framebuffer/framebuffer.h
struct PixelBox;     // framebuffer/read_pixels.h

class AccumBuffer {
 public:
  // 0 bits: no buffer (glAccum is then GL_INVALID_OPERATION).
  void resize(int width, int height, bool present);
  bool present() const { return present_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // glClear(GL_ACCUM_BUFFER_BIT): the clear value (each in [-1, 1]) into `box`.
  void clear(const PixelBox& box, const float value[4]);
  // GL_ACCUM (load false) and GL_LOAD: acc (+)= colour * value, the colour of `src`.
  void accumulate(const ColorBuffer& src, const PixelBox& box, float value, bool load);
  // GL_ADD (bias) and GL_MULT: acc += value, acc *= value.
  void scaleOrBias(const PixelBox& box, float value, bool bias);
  // GL_RETURN: colour = acc * value, clamped to [0, 1], the channels of
  // `writeMask` only.
  void returnTo(const ColorBuffer& dst, const PixelBox& box, float value, const bool writeMask[4]) const;


 private:
  size_t index(int x, int y) const { return (static_cast<size_t>(y) * width_ + x) * 4; }
  bool present_ = false;
  int width_ = 0, height_ = 0;
  std::vector<int16_t> values_;  // GL rows, bottom first
};

}  // namespace glfixed
