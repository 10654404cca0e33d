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

#include <glm/glm.hpp>

#include "raster/raster.h"
#include "state/attrib_groups.h"

namespace glfixed {

// What Mesa's fixed-function fragment program adds to a bitmap's fragments
// (st_cb_bitmap.c runs it with the bitmap's kill as a prologue; drawpix.c's
// glBitmap leaves the vertex program alone, so the program reads every input
// that the fixed-function vertex stage would not vary as a constant): the
// enabled units' texturing with the current texture coordinates, untransformed,
// and with GL_COLOR_SUM unlit the current secondary colour clamped. A unit
// whose coordinates would vary (texgen, a texture matrix, point sprites, the
// last draw's per-vertex coordinates) reads a varying: unit 0's is the
// bitmap quad's own texture coordinates, the others' and the secondary
// colour's (under lighting, or after per-vertex secondary colours) are
// absent: (0, 0, 0, 0). No fog (the variant has none: MESA_FACTS.md).
struct BitmapShading {
  bool textured = false;
  TextureAttrib texture;
  glm::vec4 texCoord[kMaxTextureUnits];
  uint32_t varyingUnits = 0;
  bool colorSum = false;
  glm::vec4 secondary{0, 0, 0, 0};
};

struct BitmapCache {
  static constexpr int kWidth = 512, kHeight = 32;
  bool empty = true;
  long long xpos = 0, ypos = 0;  // window position of the cache's bottom-left pixel
  float zpos = 0;
  float color[4] = {0, 0, 0, 0};
  bool scissorEnabled = false;  // the first bitmap's GL_SCISSOR_TEST
  // The state of the last glBitmap call (pipeline::pixelRectRasterState).
  raster::RasterState validated;
  BitmapShading shading;  // also the last glBitmap's
  std::vector<uint8_t> on;  // kWidth * kHeight, row 0 the bottom row; 1: draw
};

}  // namespace glfixed
