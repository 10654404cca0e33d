#include "pipeline/pixel_rect.h"

#include <algorithm>
#include <cmath>

#include "pipeline/draw.h"
#include "raster/pixel_rect.h"
#include "state/context.h"
#include "state/framebuffer_binding.h"

namespace glfixed::pipeline {

namespace {

// Runs `draw` into the draw buffer, or into the back then the front buffer
// from the same depth values for GL_FRONT_AND_BACK (§4.2.1; as drawBatch).
template <typename Draw>
void intoDrawBuffers(Context& ctx, Draw draw) {
  if (ctx.objectBound()) refreshFramebuffer(ctx);  // the attachments as they are now
  Framebuffer& fb = ctx.framebuffer;
  if (!fb.drawsIntoBoth(ctx.colorBuffer.drawBuffer)) return draw(fb);
  const DepthBuffer depthBefore = fb.depth;
  draw(fb);
  fb.depth = depthBefore;
  const ColorBuffer back = fb.color;
  fb.color = fb.front;
  draw(fb);
  fb.color = back;
}

// Mesa's IFLOOR of a float, saturated so that far-off positions stay ints.
int floorToInt(float v) {
  if (!(v > -1e9f)) return -1000000000;  // NaN too
  if (v > 1e9f) return 1000000000;
  return static_cast<int>(std::floor(v));
}

// Draws rows of `on` bytes (1: a fragment) or bits (`packed`), `width` wide,
// at window (x, y), as runs of pixels cut to the region.
void drawBits(Context& ctx, raster::RasterState state, long long x, long long y, int width, int height,
              const uint8_t* rows, size_t rowBytes, bool packed, float z, const float color[4],
              bool scissorEnabled) {
  if (!scissorEnabled) {  // the cache's scissor enable, not the current one
    state.scissorX0 = state.scissorY0 = 0;
    state.scissorX1 = ctx.framebuffer.width();
    state.scissorY1 = ctx.framebuffer.height();
  }
  auto isOn = [&](const uint8_t* row, int i) {
    return packed ? (row[i >> 3] & (0x80u >> (i & 7))) != 0 : row[i] != 0;
  };
  // Rows wholly outside the region draw nothing: skip them.
  const long long rowFirst = std::max<long long>(0, state.scissorY0 - y);
  const long long rowEnd = std::min<long long>(height, state.scissorY1 - y);
  intoDrawBuffers(ctx, [&](Framebuffer& fb) {
    for (long long j = rowFirst; j < rowEnd; ++j) {
      const uint8_t* row = rows + static_cast<size_t>(j) * rowBytes;
      int i = 0;
      while (i < width) {
        if (!isOn(row, i)) {
          ++i;
          continue;
        }
        int end = i + 1;
        while (end < width && isOn(row, end)) ++end;
        const long long x0 = x + i, x1 = x + end;
        if (x1 > state.scissorX0 && x0 < state.scissorX1)
          raster::drawPixelRun(state, fb, static_cast<int>(std::max<long long>(x0, state.scissorX0)),
                               static_cast<int>(y + j),
                               static_cast<int>(std::min<long long>(x1, state.scissorX1)),
                               static_cast<int>(y + j + 1), z, color);
        i = end;
      }
    }
  });
}

}  // namespace

void flushBitmapCache(Context& ctx) {
  BitmapCache& c = ctx.bitmapCache;
  if (c.empty) return;
  c.empty = true;
  if (ctx.framebuffer.bound())
    drawBits(ctx, c.validated, c.xpos, c.ypos, BitmapCache::kWidth, BitmapCache::kHeight, c.on.data(),
             BitmapCache::kWidth, false, c.zpos, c.color, c.scissorEnabled);
}

void drawBitmap(Context& ctx, int width, int height, float xorig, float yorig, const uint8_t* bits,
                bool fromList) {
  if (!ctx.framebuffer.bound() || width <= 0 || height <= 0 || !bits) return;
  const RasterPosState& rp = ctx.rasterPos;
  const float epsilon = 0.0001f;
  const long long x = floorToInt(rp.position.x + epsilon - xorig);
  const long long y = floorToInt(rp.position.y + epsilon - yorig);
  const float z = rp.position.z;
  const float color[4] = {rp.color.r, rp.color.g, rp.color.b, rp.color.a};
  const bool scissorEnabled = ctx.scissor.test;
  const size_t rowBytes = static_cast<size_t>(bitmapRowBytes(width));
  BitmapCache& c = ctx.bitmapCache;
  if (fromList) flushBitmapCache(ctx);
  const raster::RasterState state = pixelRectRasterState(ctx);
  c.validated = state;  // st_Bitmap validates before it accumulates
  if (fromList || width > BitmapCache::kWidth || height > BitmapCache::kHeight)
    return drawBits(ctx, state, x, y, width, height, bits, rowBytes, true, z, color, scissorEnabled);
  // accum_bitmap: does it fit in the cache with the same colour and depth?
  long long px = 0, py = 0;
  if (!c.empty) {
    px = x - c.xpos;
    py = y - c.ypos;
    const bool sameColor =
        c.color[0] == color[0] && c.color[1] == color[1] && c.color[2] == color[2] && c.color[3] == color[3];
    if (px < 0 || px + width > BitmapCache::kWidth || py < 0 || py + height > BitmapCache::kHeight ||
        !sameColor || scissorEnabled != c.scissorEnabled || std::fabs(z - c.zpos) > 1e-06f)
      flushBitmapCache(ctx);
  }
  if (c.empty) {  // a new cache, the bitmap centred vertically in it
    px = 0;
    py = (BitmapCache::kHeight - height) / 2;
    c.xpos = x;
    c.ypos = y - py;
    c.zpos = z;
    for (int k = 0; k < 4; ++k) c.color[k] = color[k];
    c.scissorEnabled = scissorEnabled;
    c.on.assign(size_t(BitmapCache::kWidth) * BitmapCache::kHeight, 0);
    c.empty = false;
  }
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      if (bits[j * rowBytes + (i >> 3)] & (0x80u >> (i & 7)))
        c.on[size_t(py + j) * BitmapCache::kWidth + size_t(px + i)] = 1;
}

}  // namespace glfixed::pipeline
