// Client pixels <-> stored texels for the texture commands (GL 2.1 §3.6:
// unpacking, tables 3.5-3.8; §6.1.4: glGetTexImage packs the other way).
// A pixel goes through float RGBA, as Mesa's texstore does when the client
// data is not already in the stored layout; the roundings are Mesa's
// (probed: reference/MESA_FACTS.md "Textures: storage").
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "state/attrib_groups.h"
#include "state/attribs.h"
#include "state/pixel_maps.h"
#include "texture/texture_object.h"

namespace glfixed::texture {

// A packed type (GL 2.1 table 3.8): its size in bytes and the widths of its
// fields in component order; REV types put the first component in the low
// bits. bytes is 0 for a type that is not packed (and for GL_BITMAP).
struct Packed {
  int bytes = 0;
  int fields = 0;
  int width[4] = {0, 0, 0, 0};
  bool reversed = false;
};
Packed packedType(GLenum type);
// One pixel's components as a packed element, rounded as Mesa packs them
// (unpack.cpp; glReadPixels and glGetTexImage).
uint32_t packElement(const Packed& packed, const float c[4], const uint8_t b[4], bool viaBytes, bool replicateBytes);

// The error a (format, type) pair of client pixel data gives (GL 2.1
// §3.6.4; Mesa's _mesa_error_check_format_and_type): GL_INVALID_ENUM for an
// unknown format or type or GL_BITMAP with a colour format,
// GL_INVALID_OPERATION for a packed type with a format of another
// component count; GL_NO_ERROR otherwise.
GLenum checkFormatAndType(GLenum format, GLenum type);

// Where the pixels of a client image lie (§3.6.4: row length, alignment,
// skips, image height).
struct ClientLayout {
  size_t groupBytes = 0;   // one pixel (0 for GL_BITMAP: bits)
  size_t rowStride = 0;    // bytes
  size_t imageStride = 0;  // bytes
  size_t start = 0;        // byte offset of the first pixel read
  int elementBytes = 1;    // the size the swap-bytes rule swaps
  bool swapBytes = false;
  bool bitmap = false;
  int skipBits = 0;  // GL_BITMAP: skip pixels within the first byte
  int rowPixels = 0;  // the row length, or the width
  bool invertRows = false;  // GL_MESA_pack_invert: the image's top row is written first
  // Bytes from the start of the client memory to the end of the last pixel
  // of a width x height x depth image (0 for an empty image).
  size_t extent(int width, int height, int depth) const;
};
ClientLayout unpackLayout(const PixelStoreAttrib& store, int width, int height, GLenum format, GLenum type);
ClientLayout packLayout(const PixelStoreAttrib& store, int width, int height, GLenum format, GLenum type);

// Unpacks a width x height x depth client image into `image` at (x, y, z),
// converted to the image's stored format, pixel transfer's scale and bias
// applied (§3.6.5), then with `maps` and GL_MAP_COLOR the colour maps
// (PixelMap::atColor, Mesa's texstore). GL_COLOR_INDEX images: each index
// shifted and offset (GL_INDEX_SHIFT, _OFFSET), then through `maps`'
// I_TO_R .. I_TO_A (no scale, bias or colour maps; Mesa's texstore). `pixels` is at least
// layout.extent(...) bytes.
void unpackImage(const ClientLayout& layout, const uint8_t* pixels, GLenum format, GLenum type,
                 const PixelModeAttrib& transfer, int width, int height, int depth, TextureImage& image,
                 int x, int y, int z, const PixelMaps* maps = nullptr);

// Colour index (i, j) of a client image (§3.6.4) as Mesa extracts it: the
// integer (floats truncated through a 64-bit integer, negative values
// wrapped as unsigned). GL_BITMAP as Mesa reads it (measured): the rows as
// one run of bits, not padded to bytes, pixel (i, j) bit 2 * skipBits +
// j * rowPixels + i from the first byte.
uint32_t clientColorIndex(const ClientLayout& layout, const uint8_t* pixels, GLenum type, int i, int j);

// Packs a whole level into client memory (glGetTexImage, §6.1.4): the stored
// components as R, G, B, A (luminance to R, intensity to R, table 6.1).
void packImage(const TextureImage& image, const ClientLayout& layout, GLenum format, GLenum type,
               uint8_t* pixels);

// One texel of `format` from a float RGBA already mapped to the base format
// (the conversion to the stored precision, Mesa's rounding).
void storeTexel(TexelFormat format, const float rgba[4], uint8_t* texel);

}  // namespace glfixed::texture
