// A small RGBA framebuffer with a depth buffer for raster and primitive tests.
#pragma once

#include <cstdint>
#include <vector>

#include "framebuffer/framebuffer.h"
#include "raster/raster.h"

namespace glfixed::test {

struct TestSurface {
  std::vector<uint8_t> pixels;
  Framebuffer fb;

  TestSurface(int width, int height, int depthBits = 24) : pixels(size_t(width) * height * 4, 0) {
    fb.color.pixels = pixels.data();
    fb.color.width = width;
    fb.color.height = height;
    fb.color.rowLength = width;
    fb.color.setFormat(PixelFormat::kRGBA);
    fb.front = fb.readFront = fb.color;
    fb.depth.resize(width, height, depthBits);
    if (depthBits) fb.depth.fill(fb.depth.maxValue());
  }
  int width() const { return fb.width(); }
  int height() const { return fb.height(); }
  // GL window coordinates (y up).
  const uint8_t* at(int x, int y) const { return fb.color.pixel(x, y); }
  bool covered(int x, int y) const {
    const uint8_t* p = at(x, y);
    return p[0] | p[1] | p[2] | p[3];
  }
  int coveredCount() const {
    int n = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) n += covered(x, y);
    return n;
  }
  void clear() {
    std::fill(pixels.begin(), pixels.end(), 0);
    if (fb.depth.bits()) fb.depth.fill(fb.depth.maxValue());
  }
  // Raster state writing everywhere, no depth test.
  raster::RasterState state() const {
    raster::RasterState s;
    s.scissorX1 = width();
    s.scissorY1 = height();
    return s;
  }
  // A window vertex from GL window coordinates (y up), with colour.
  raster::WindowVertex vertex(float x, float yGL, float z = 0.5f, float r = 1, float g = 1, float b = 1,
                              float a = 1) const {
    raster::WindowVertex v;
    v.x = x;
    v.y = static_cast<float>(height()) - yGL;
    v.z = z;
    v.varying[0] = r;
    v.varying[1] = g;
    v.varying[2] = b;
    v.varying[3] = a;
    return v;
  }
};

}  // namespace glfixed::test
