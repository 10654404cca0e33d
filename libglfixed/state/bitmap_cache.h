// Mesa's bitmap cache (st_cb_bitmap.c): glBitmap calls that fit in one
// 512 x 32 pixel window and share the raster colour, depth and the scissor
// enable are gathered and drawn together later, when another bitmap does not
// fit, or at the next draw, clear, read, copy or flush. They are drawn with
// the gallium state last validated, which is the fragment state (depth test,
// masks, scissor box) of the LAST glBitmap call (st_Bitmap validates before
// it accumulates; draws and clears flush before they validate), not each
// call's own: a Mesa departure from GL 2.1 §3.7, matched
// (reference/MESA_FACTS.md "Pixel rectangles"; pipeline/pixel_rect.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "raster/raster.h"

namespace glfixed {

struct BitmapCache {
  static constexpr int kWidth = 512, kHeight = 32;
  bool empty = true;
  long long xpos = 0, ypos = 0;  // window position of the cache's bottom-left pixel
  float zpos = 0;
  float color[4] = {0, 0, 0, 0};
  bool scissorEnabled = false;  // the first bitmap's GL_SCISSOR_TEST
  // The state of the last glBitmap call (pipeline::pixelRectRasterState).
  raster::RasterState validated;
  std::vector<uint8_t> on;  // kWidth * kHeight, row 0 the bottom row; 1: draw
};

}  // namespace glfixed
