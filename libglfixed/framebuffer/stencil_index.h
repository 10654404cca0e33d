// The pixel transfer of a stencil index (GL 2.1 §3.6.5, "Arithmetic on
// Indices" and "Stencil Index Lookup"): shifted by GL_INDEX_SHIFT, offset by
// GL_INDEX_OFFSET, then, with GL_MAP_STENCIL, looked up in the S_TO_S map
// (a map value cut to a byte, as Mesa's GLubyte cast);
// the result kept to the 8 bits of the stencil buffer.
//
// Where Mesa 22.3 applies it (measured, reference/MESA_FACTS.md): to
// glReadPixels(GL_STENCIL_INDEX) only. Its glDrawPixels of stencil stores
// the image with the transfer state cleared, and glCopyPixels(GL_STENCIL)
// blits the source, so neither shifts, offsets nor maps.
#pragma once

#include <cstdint>

#include "state/attrib_groups.h"
#include "state/pixel_maps.h"

namespace glfixed {

inline uint8_t transferStencilIndex(const PixelModeAttrib& pm, const PixelMaps* maps, uint32_t index) {
  // Mesa shifts a 32-bit index in C: x86 takes the count modulo 32
  // (measured: a shift of 33 is a shift of 1, of -32 none).
  const int shift = pm.indexShift;
  if (shift > 0)
    index <<= static_cast<unsigned>(shift) & 31u;
  else if (shift < 0)
    index >>= static_cast<unsigned>(-static_cast<int64_t>(shift)) & 31u;
  index += static_cast<uint32_t>(pm.indexOffset);
  // GL's default map (one entry, 0) reads every value as 0, as on Mesa.
  if (pm.mapStencil && maps) index = static_cast<uint32_t>(maps->mapStencil(index));
  return static_cast<uint8_t>(index);
}

}  // namespace glfixed
