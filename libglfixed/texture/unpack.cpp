#include "texture/unpack.h"

#include <algorithm>
#include <cmath>
#include <cstring>

// EXT_packed_depth_stencil and ARB_depth_buffer_float (not in GL 2.1's gl.h).
#ifndef GL_DEPTH_STENCIL
#define GL_DEPTH_STENCIL 0x84F9
#endif
#ifndef GL_UNSIGNED_INT_24_8
#define GL_UNSIGNED_INT_24_8 0x84FA
#endif
#ifndef GL_FLOAT_32_UNSIGNED_INT_24_8_REV
#define GL_FLOAT_32_UNSIGNED_INT_24_8_REV 0x8DAD
#endif

namespace glfixed::texture {

Packed packedType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: return {1, 3, {3, 3, 2, 0}, false};
    case GL_UNSIGNED_BYTE_2_3_3_REV: return {1, 3, {3, 3, 2, 0}, true};
    case GL_UNSIGNED_SHORT_5_6_5: return {2, 3, {5, 6, 5, 0}, false};
    case GL_UNSIGNED_SHORT_5_6_5_REV: return {2, 3, {5, 6, 5, 0}, true};
    case GL_UNSIGNED_SHORT_4_4_4_4: return {2, 4, {4, 4, 4, 4}, false};
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: return {2, 4, {4, 4, 4, 4}, true};
    case GL_UNSIGNED_SHORT_5_5_5_1: return {2, 4, {5, 5, 5, 1}, false};
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return {2, 4, {5, 5, 5, 1}, true};
    case GL_UNSIGNED_INT_8_8_8_8: return {4, 4, {8, 8, 8, 8}, false};
    case GL_UNSIGNED_INT_8_8_8_8_REV: return {4, 4, {8, 8, 8, 8}, true};
    case GL_UNSIGNED_INT_10_10_10_2: return {4, 4, {10, 10, 10, 2}, false};
    case GL_UNSIGNED_INT_2_10_10_10_REV: return {4, 4, {10, 10, 10, 2}, true};
    default: return {};
  }
}

namespace {

bool isDepthStencilType(GLenum type) {
  return type == GL_UNSIGNED_INT_24_8 || type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
}

int componentsOf(GLenum format) {
  switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_STENCIL:  // one group of a depth-stencil type
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB:
    case GL_BGR: return 3;
    case GL_RGBA:
    case GL_BGRA: return 4;
    default: return 0;
  }
}

int elementBytes(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE:
    case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT:
    case GL_SHORT:
    case GL_HALF_FLOAT_ARB: return 2;
    case GL_UNSIGNED_INT:
    case GL_INT:
    case GL_FLOAT:
    case GL_UNSIGNED_INT_24_8:
    case GL_FLOAT_32_UNSIGNED_INT_24_8_REV: return 4;  // (two of them a group)
    default: return packedType(type).bytes;
  }
}

ClientLayout layoutOf(int alignment, int rowLength, int skipPixels, int skipRows, int imageHeight,
                      int skipImages, bool swap, int width, int height, GLenum format, GLenum type) {
  ClientLayout l;
  const size_t rowPixels = static_cast<size_t>(rowLength > 0 ? rowLength : width);
  l.rowPixels = static_cast<int>(rowPixels);
  const size_t align = static_cast<size_t>(alignment);
  if (type == GL_BITMAP) {  // §3.6.4: rows of bits, padded to the alignment
    l.bitmap = true;
    l.rowStride = (rowPixels + 8 * align - 1) / (8 * align) * align;
    l.start = static_cast<size_t>(skipPixels) / 8;
    l.skipBits = skipPixels % 8;
  } else {
    const Packed packed = packedType(type);
    l.elementBytes = elementBytes(type);
    l.groupBytes = packed.bytes ? packed.bytes : static_cast<size_t>(componentsOf(format)) * l.elementBytes;
    if (type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV) l.groupBytes = 8;  // a float depth, then the stencil word
    l.rowStride = rowPixels * l.groupBytes;
    if (static_cast<size_t>(l.elementBytes) < align) l.rowStride = (l.rowStride + align - 1) / align * align;
    l.start = static_cast<size_t>(skipPixels) * l.groupBytes;
    l.swapBytes = swap && l.elementBytes > 1;
  }
  l.imageStride = l.rowStride * static_cast<size_t>(imageHeight > 0 ? imageHeight : height);
  l.start += static_cast<size_t>(skipRows) * l.rowStride + static_cast<size_t>(skipImages) * l.imageStride;
  return l;
}

uint32_t readElement(const uint8_t* p, int bytes, bool swap) {
  uint8_t b[4];
  for (int i = 0; i < bytes; ++i) b[i] = p[swap ? bytes - 1 - i : i];
  switch (bytes) {
    case 1: return b[0];
    case 2: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    default: {
      uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
  }
}

// An element of a non-packed type as a float (GL 2.1 table 2.9, with the
// signed rule of GL 3: max(c / (2^(b-1) - 1), -1), which Mesa uses).
float elementToFloat(uint32_t bits, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<float>(bits) * (1.0f / 255.0f);
    case GL_BYTE: return std::max(static_cast<float>(static_cast<int8_t>(bits)) / 127.0f, -1.0f);
    case GL_UNSIGNED_SHORT: return static_cast<float>(bits) * (1.0f / 65535.0f);
    case GL_SHORT: return std::max(static_cast<float>(static_cast<int16_t>(bits)) / 32767.0f, -1.0f);
    case GL_UNSIGNED_INT: return static_cast<float>(double(bits) / 4294967295.0);
    case GL_INT: return static_cast<float>(std::max(double(static_cast<int32_t>(bits)) / 2147483647.0, -1.0));
    case GL_FLOAT: {
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    case GL_HALF_FLOAT_ARB: return halfToFloat(static_cast<uint16_t>(bits));  // ARB_half_float_pixel
    default: return 0;
  }
}

// The components of one group, in the order of `format`. `replicate`: a
// packed field narrower than 8 bits reads as its bits repeated to 8, over
// 255 (Mesa converts such data to 8-bit storage unorm to unorm, by bit
// replication: 5-bit 3 -> 24, 6-bit 49 -> 199; MESA_FACTS.md "Textures:
// storage"); the stored value then comes out the same at 8 bits and at the
// field's own width.
void readComponents(const uint8_t* p, GLenum type, int components, bool swap, bool replicate, float c[4]) {
  const Packed packed = packedType(type);
  if (packed.bytes) {
    const uint32_t v = readElement(p, packed.bytes, swap);
    int used = 0;
    const int total = packed.bytes * 8;
    for (int i = 0; i < packed.fields; ++i) {
      const int w = packed.width[i];
      const int shift = packed.reversed ? used : total - used - w;
      used += w;
      const uint32_t field = (v >> shift) & ((1u << w) - 1);
      if (replicate && w < 8) {
        uint32_t b = 0;
        for (int s = 8 - w; s > -w; s -= w) b |= s >= 0 ? field << s : field >> -s;
        c[i] = static_cast<float>(b & 255u) / 255.0f;
      } else {
        c[i] = static_cast<float>(field) / static_cast<float>((1u << w) - 1);
      }
    }
    return;
  }
  const int bytes = elementBytes(type);
  for (int i = 0; i < components; ++i) c[i] = elementToFloat(readElement(p + i * bytes, bytes, swap), type);
}

// §3.6.4 "conversion to RGBA" (luminance to R, G and B).
void toRGBA(GLenum format, const float c[4], float rgba[4]) {
  rgba[0] = rgba[1] = rgba[2] = 0;
  rgba[3] = 1;
  switch (format) {
    case GL_RED: rgba[0] = c[0]; break;
    case GL_GREEN: rgba[1] = c[0]; break;
    case GL_BLUE: rgba[2] = c[0]; break;
    case GL_ALPHA: rgba[3] = c[0]; break;
    case GL_RGB: rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2]; break;
    case GL_BGR: rgba[0] = c[2], rgba[1] = c[1], rgba[2] = c[0]; break;
    case GL_RGBA: rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2], rgba[3] = c[3]; break;
    case GL_BGRA: rgba[0] = c[2], rgba[1] = c[1], rgba[2] = c[0], rgba[3] = c[3]; break;
    case GL_LUMINANCE: rgba[0] = rgba[1] = rgba[2] = c[0]; break;
    case GL_LUMINANCE_ALPHA: rgba[0] = rgba[1] = rgba[2] = c[0], rgba[3] = c[1]; break;
    case GL_DEPTH_COMPONENT: rgba[0] = c[0]; break;
    default:  // GL_COLOR_INDEX: through the default one-entry maps (all 0)
      rgba[3] = 0;
      break;
  }
}

float clamp01(float v) { return v > 0 ? (v < 1 ? v : 1) : 0; }

void writeChannel(uint8_t* p, int bytes, uint32_t v) {
  for (int i = 0; i < bytes; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}

// Stored channels from float values; `fromBytes`: the values came from 8-bit
// unsigned client data, which Mesa widens to more than 8 bits by repeating
// the bits (probed: 10-bit channels get (b << 2) | (b >> 6)).
void storeChannels(TexelFormat format, const float c[4], bool fromBytes, uint8_t* texel) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  for (int i = 0; i < info.channels; ++i) {
    const int bits = info.bits[i];
    uint32_t v = 0;
    const float f = clamp01(c[i]);
    if (info.floating) {  // ARB_texture_float: kept as it is, not clamped
      if (bits == 16) {
        v = floatToHalf(c[i]);
      } else if (bits == 32) {
        std::memcpy(&v, &c[i], 4);
      }
    } else if (bits == 0) {
      v = 0;
    } else if (fromBytes && bits > 8) {
      const uint32_t b = static_cast<uint32_t>(std::nearbyint(f * 255.0f));
      for (int shift = bits - 8; shift > -8; shift -= 8) v |= shift >= 0 ? b << shift : b >> -shift;
    } else if (bits <= 16) {
      // Mesa's _mesa_float_to_unorm: round to nearest even, in float.
      v = static_cast<uint32_t>(std::nearbyint(f * static_cast<float>((1u << bits) - 1)));
    } else if (bits == 24 && info.baseFormat == GL_DEPTH_COMPONENT) {
      // Mesa's 24-bit depth store (Z24X8 and Z24_UNORM_S8_UINT alike) truncates:
      // 0.25 stores 0x3fffff (measured).
      v = static_cast<uint32_t>(double(f) * 16777215.0);
    } else {
      const double max = bits == 32 ? 4294967295.0 : double((1u << bits) - 1);
      v = static_cast<uint32_t>(std::nearbyint(double(f) * max));
    }
    writeChannel(texel + i * info.bytesPerChannel, info.bytesPerChannel, v);
  }
}

// RGBA (or depth in [0]) to the stored channels of a base format.
void rgbaToChannels(GLenum base, const float rgba[4], float c[4]) {
  c[0] = c[1] = c[2] = c[3] = 0;
  switch (base) {
    case GL_ALPHA: c[0] = rgba[3]; break;
    case GL_LUMINANCE:
    case GL_INTENSITY:
    case GL_DEPTH_COMPONENT: c[0] = rgba[0]; break;
    case GL_LUMINANCE_ALPHA: c[0] = rgba[0], c[1] = rgba[3]; break;
    default: c[0] = rgba[0], c[1] = rgba[1], c[2] = rgba[2], c[3] = rgba[3]; break;
  }
}

}  // namespace

GLenum checkFormatAndType(GLenum format, GLenum type) {
  if (componentsOf(format) == 0) return GL_INVALID_ENUM;
  if (type == GL_BITMAP)
    return format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX ? GL_NO_ERROR : GL_INVALID_ENUM;
  if (elementBytes(type) == 0) return GL_INVALID_ENUM;
  // EXT_packed_depth_stencil (and ARB_depth_buffer_float's type): the format
  // only with its types (else GL_INVALID_ENUM), the types only with it
  // (else GL_INVALID_OPERATION), as Mesa answers.
  if (format == GL_DEPTH_STENCIL) return isDepthStencilType(type) ? GL_NO_ERROR : GL_INVALID_ENUM;
  if (isDepthStencilType(type)) return GL_INVALID_OPERATION;
  const Packed packed = packedType(type);
  if (packed.bytes && packed.fields != componentsOf(format)) return GL_INVALID_OPERATION;
  // The three-field types take GL_RGB only (GL 2.1 table 3.8; Mesa refuses GL_BGR).
  if (packed.fields == 3 && format != GL_RGB) return GL_INVALID_OPERATION;
  if (packed.fields == 4 && format != GL_RGBA && format != GL_BGRA) return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

size_t ClientLayout::extent(int width, int height, int depth) const {
  if (width <= 0 || height <= 0 || depth <= 0) return 0;
  const size_t lastRow =
      bitmap ? (static_cast<size_t>(skipBits) + width + 7) / 8 : static_cast<size_t>(width) * groupBytes;
  return start + (static_cast<size_t>(depth) - 1) * imageStride +
         (static_cast<size_t>(height) - 1) * rowStride + lastRow;
}

ClientLayout unpackLayout(const PixelStoreAttrib& s, int width, int height, GLenum format, GLenum type) {
  return layoutOf(s.unpackAlignment, s.unpackRowLength, s.unpackSkipPixels, s.unpackSkipRows,
                  s.unpackImageHeight, s.unpackSkipImages, s.unpackSwapBytes, width, height, format, type);
}

ClientLayout packLayout(const PixelStoreAttrib& s, int width, int height, GLenum format, GLenum type) {
  ClientLayout layout = layoutOf(s.packAlignment, s.packRowLength, s.packSkipPixels, s.packSkipRows,
                                 s.packImageHeight, s.packSkipImages, false, width, height, format, type);
  layout.invertRows = s.packInvert != GL_FALSE;
  return layout;
}

void storeTexel(TexelFormat format, const float rgba[4], uint8_t* texel) {
  float c[4];
  rgbaToChannels(texelFormatInfo(format).baseFormat, rgba, c);
  storeChannels(format, c, false, texel);
}

uint32_t clientColorIndex(const ClientLayout& layout, const uint8_t* pixels, GLenum type, int i, int j) {
  if (layout.bitmap) {
    const size_t bit = layout.start * 8 + size_t(2 * layout.skipBits) + size_t(j) * size_t(layout.rowPixels) + size_t(i);
    return (pixels[bit / 8] >> (7 - bit % 8)) & 1u;
  }
  const uint8_t* p = pixels + layout.start + size_t(j) * layout.rowStride + size_t(i) * layout.groupBytes;
  switch (type) {
    case GL_UNSIGNED_BYTE: return *p;
    case GL_BYTE: return static_cast<uint32_t>(static_cast<int8_t>(*p));
    case GL_UNSIGNED_SHORT: return readElement(p, 2, layout.swapBytes);
    case GL_SHORT: return static_cast<uint32_t>(static_cast<int16_t>(readElement(p, 2, layout.swapBytes)));
    case GL_FLOAT: {
      const uint32_t bits = readElement(p, 4, layout.swapBytes);
      float f;
      std::memcpy(&f, &bits, 4);
      // (GLuint) f as x86-64 converts it: through a 64-bit integer.
      return f > -9.2e18f && f < 9.2e18f ? static_cast<uint32_t>(static_cast<int64_t>(f)) : 0u;
    }
    case GL_HALF_FLOAT_ARB: {
      const float f = halfToFloat(static_cast<uint16_t>(readElement(p, 2, layout.swapBytes)));
      return f > -9.2e18f && f < 9.2e18f ? static_cast<uint32_t>(static_cast<int64_t>(f)) : 0u;
    }
    default: return readElement(p, 4, layout.swapBytes);  // GL_UNSIGNED_INT, GL_INT
  }
}

namespace {

// Where each stored byte of an 8-bit texel comes from when GL_UNSIGNED_BYTE
// components are stored with no pixel transfer: a client component, or 0 or
// 255. The general path's float arithmetic gives the byte back unchanged
// (rint(b / 255 * 255) = b), so the mapping is read off that path's own
// rearrangement (toRGBA, rgbaToChannels) applied to marker values.
struct ByteCopy {
  static constexpr int kZero = -1, kOne = -2;
  int source[4] = {kZero, kZero, kZero, kZero};
  int channels = 0;
};

bool byteCopyOf(const TexelFormatInfo& info, GLenum format, ByteCopy& copy) {
  if (info.bytesPerChannel != 1 || format == GL_COLOR_INDEX || format == GL_DEPTH_COMPONENT ||
      format == GL_STENCIL_INDEX)
    return false;
  for (int i = 0; i < info.channels; ++i)
    if (info.bits[i] != 8 && info.bits[i] != 0) return false;
  const float markers[4] = {10, 20, 30, 40};
  float rgba[4], channels[4];
  toRGBA(format, markers, rgba);
  rgbaToChannels(info.baseFormat, rgba, channels);
  copy.channels = info.channels;
  for (int i = 0; i < info.channels; ++i) {
    const float m = channels[i];
    if (info.bits[i] == 0 || m == 0.0f) copy.source[i] = ByteCopy::kZero;
    else if (m == 1.0f) copy.source[i] = ByteCopy::kOne;
    else copy.source[i] = static_cast<int>(m) / 10 - 1;
  }
  return true;
}

void copyBytes(const ByteCopy& copy, const uint8_t* in, size_t inStride, uint8_t* out, int width) {
  const int n = copy.channels;
  for (int i = 0; i < width; ++i, in += inStride, out += n)
    for (int k = 0; k < n; ++k) {
      const int src = copy.source[k];
      out[k] = src >= 0 ? in[src] : src == ByteCopy::kOne ? 255 : 0;
    }
}

// One GL_DEPTH_STENCIL group into a depth (or depth-stencil) texel: Z24 and
// Z24S8 take the 24 bits as they are (Mesa's texstore copies them; the
// stencil only where the texture has one), the other depth formats the
// depth as a value in [0, 1]. Pixel transfer (§3.6.5) as Mesa applies it:
// the depth scale and bias to the depth as a float, stored truncated (0.5
// stores 0x111111 as 0x088888), GL_INDEX_SHIFT and _OFFSET to the stencil.
void unpackDepthStencil(const uint8_t* p, GLenum type, bool swap, const PixelModeAttrib& transfer,
                        TexelFormat format, uint8_t* texel) {
  uint32_t depth24, stencil;
  float depth;
  const bool scaleBias = transfer.depthScale != 1 || transfer.depthBias != 0;
  if (type == GL_UNSIGNED_INT_24_8) {
    const uint32_t v = readElement(p, 4, swap);
    depth24 = v >> 8;
    stencil = v & 0xffu;
    depth = static_cast<float>(depth24) / 16777215.0f;
  } else {  // GL_FLOAT_32_UNSIGNED_INT_24_8_REV: truncated to 24 bits (0.25 stores 0x3fffff)
    depth = clamp01(elementToFloat(readElement(p, 4, swap), GL_FLOAT));
    stencil = readElement(p + 4, 4, swap) & 0xffu;
    depth24 = static_cast<uint32_t>(double(depth) * 16777215.0);
  }
  if (scaleBias) {
    depth = clamp01(depth * transfer.depthScale + transfer.depthBias);
    depth24 = static_cast<uint32_t>(double(depth) * 16777215.0);
  }
  if (transfer.indexShift != 0 || transfer.indexOffset != 0) {
    const int shift = transfer.indexShift;
    stencil = ((shift >= 0 ? stencil << (shift & 31) : stencil >> ((-shift) & 31)) +
               static_cast<uint32_t>(transfer.indexOffset)) & 0xffu;
  }
  if (format == TexelFormat::Z24 || format == TexelFormat::Z24S8) {
    writeChannel(texel, 4, depth24 | (format == TexelFormat::Z24S8 ? stencil << 24 : 0u));
    return;
  }
  const float c[4] = {depth, 0, 0, 0};
  storeChannels(format, c, false, texel);
}

}  // namespace

void unpackImage(const ClientLayout& layout, const uint8_t* pixels, GLenum format, GLenum type,
                 const PixelModeAttrib& transfer, int width, int height, int depth, TextureImage& image,
                 int x, int y, int z, const PixelMaps* maps) {
  const TexelFormatInfo& info = texelFormatInfo(image.format);
  const bool isDepth = format == GL_DEPTH_COMPONENT;
  const bool mapColor = !isDepth && maps && transfer.mapColor;
  const bool scaleBias = isDepth ? (transfer.depthScale != 1 || transfer.depthBias != 0)
                                 : (transfer.scale != glm::vec4(1) || transfer.bias != glm::vec4(0) || mapColor);
  ByteCopy copy;
  if (type == GL_UNSIGNED_BYTE && !scaleBias && !layout.bitmap && byteCopyOf(info, format, copy)) {
    const bool identity = copy.channels == componentsOf(format) && layout.groupBytes == size_t(copy.channels) &&
                          [&] {
                            for (int k = 0; k < copy.channels; ++k)
                              if (copy.source[k] != k) return false;
                            return true;
                          }();
    for (int k = 0; k < depth; ++k)
      for (int j = 0; j < height; ++j) {
        const uint8_t* row = pixels + layout.start + size_t(k) * layout.imageStride + size_t(j) * layout.rowStride;
        uint8_t* out = image.texels.data() + size_t(z + k) * image.imageStride + size_t(y + j) * image.rowStride +
                       size_t(x) * info.bytesPerTexel;
        if (identity)
          std::memcpy(out, row, size_t(width) * info.bytesPerTexel);
        else
          copyBytes(copy, row, layout.groupBytes, out, width);
      }
    return;
  }
  const bool fromBytes = !scaleBias && (type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_INT_8_8_8_8 ||
                                        type == GL_UNSIGNED_INT_8_8_8_8_REV);
  const int components = componentsOf(format);
  for (int k = 0; k < depth; ++k) {
    for (int j = 0; j < height; ++j) {
      const uint8_t* row =
          pixels + layout.start + size_t(k) * layout.imageStride + size_t(j) * layout.rowStride;
      uint8_t* out = image.texels.data() + size_t(z + k) * image.imageStride +
                     size_t(y + j) * image.rowStride + size_t(x) * info.bytesPerTexel;
      for (int i = 0; i < width; ++i, out += info.bytesPerTexel) {
        float c[4] = {0, 0, 0, 0}, rgba[4];
        if (format == GL_DEPTH_STENCIL) {
          unpackDepthStencil(row + size_t(i) * layout.groupBytes, type, layout.swapBytes, transfer, image.format,
                             out);
          continue;
        }
        if (format == GL_COLOR_INDEX) {  // §3.6.5: index arithmetic, then index to RGBA
          ClientLayout slice = layout;
          slice.start += size_t(k) * layout.imageStride;
          uint32_t index = clientColorIndex(slice, pixels, type, i, j);
          const int shift = transfer.indexShift;
          index = (shift >= 0 ? index << (shift & 31) : index >> ((-shift) & 31)) +
                  static_cast<uint32_t>(transfer.indexOffset);
          for (int n = 0; n < 4; ++n) rgba[n] = maps ? (*maps)[GL_PIXEL_MAP_I_TO_R + n].atIndex(index) : 0.0f;
          float channels[4];
          rgbaToChannels(info.baseFormat, rgba, channels);
          storeChannels(image.format, channels, false, out);
          continue;
        }
        if (!layout.bitmap)
          readComponents(row + size_t(i) * layout.groupBytes, type, components, layout.swapBytes, !scaleBias, c);
        toRGBA(format, c, rgba);
        if (scaleBias) {  // §3.6.5: pixel transfer, then the clamp to [0, 1]
          if (isDepth) {
            rgba[0] = rgba[0] * transfer.depthScale + transfer.depthBias;
          } else {
            for (int n = 0; n < 4; ++n) rgba[n] = rgba[n] * transfer.scale[n] + transfer.bias[n];
            if (mapColor)
              for (int n = 0; n < 4; ++n) rgba[n] = (*maps)[GL_PIXEL_MAP_R_TO_R + n].atColor(rgba[n]);
          }
        }
        float channels[4];
        rgbaToChannels(info.baseFormat, rgba, channels);
        storeChannels(image.format, channels, fromBytes, out);
      }
    }
  }
}

namespace {

// Table 6.1: the stored components as R, G, B, A for glGetTexImage.
void texelToRGBA(TexelFormat format, const uint8_t* texel, float rgba[4]) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  float c[4] = {0, 0, 0, 0};
  for (int i = 0; i < info.channels; ++i) {
    if (!info.bits[i]) continue;
    if (info.floating) {
      c[i] = storedFloat(format, texel, i);
      continue;
    }
    const uint32_t v = storedChannel(format, texel, i);
    c[i] = info.bits[i] == 32 ? static_cast<float>(double(v) / 4294967295.0)
                              : static_cast<float>(v) / static_cast<float>((1u << info.bits[i]) - 1);
  }
  rgba[0] = rgba[1] = rgba[2] = 0;
  rgba[3] = 1;
  switch (info.baseFormat) {
    case GL_ALPHA: rgba[3] = c[0]; break;
    case GL_LUMINANCE:
    case GL_INTENSITY:
    case GL_DEPTH_COMPONENT: rgba[0] = c[0]; break;
    case GL_LUMINANCE_ALPHA: rgba[0] = c[0], rgba[3] = c[1]; break;
    case GL_RGB: rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2]; break;
    default: rgba[0] = c[0], rgba[1] = c[1], rgba[2] = c[2], rgba[3] = c[3]; break;
  }
}

uint32_t floatToElement(float f, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return static_cast<uint32_t>(std::nearbyint(clamp01(f) * 255.0f));
    case GL_BYTE:
      return static_cast<uint8_t>(static_cast<int8_t>(std::nearbyint(std::clamp(f, -1.0f, 1.0f) * 127.0f)));
    case GL_UNSIGNED_SHORT: return static_cast<uint32_t>(std::nearbyint(clamp01(f) * 65535.0f));
    case GL_SHORT:
      return static_cast<uint16_t>(
          static_cast<int16_t>(std::nearbyint(std::clamp(f, -1.0f, 1.0f) * 32767.0f)));
    case GL_UNSIGNED_INT: return static_cast<uint32_t>(std::nearbyint(double(clamp01(f)) * 4294967295.0));
    case GL_INT:
      return static_cast<uint32_t>(
          static_cast<int32_t>(std::nearbyint(double(std::clamp(f, -1.0f, 1.0f)) * 2147483647.0)));
    case GL_FLOAT: {
      uint32_t v;
      std::memcpy(&v, &f, 4);
      return v;
    }
    case GL_HALF_FLOAT_ARB: return floatToHalfNearest(f);
    default: return 0;
  }
}

void writeElement(uint8_t* p, int bytes, uint32_t v) {
  switch (bytes) {
    case 1: p[0] = static_cast<uint8_t>(v); break;
    case 2: {
      uint16_t s = static_cast<uint16_t>(v);
      std::memcpy(p, &s, 2);
      break;
    }
    default: std::memcpy(p, &v, 4); break;
  }
}

// One Z24S8 texel as GL_DEPTH_STENCIL (the depth in the top 24 bits of
// GL_UNSIGNED_INT_24_8, as a float before the stencil word of
// GL_FLOAT_32_UNSIGNED_INT_24_8_REV) or as GL_STENCIL_INDEX, the index
// Formats whose packed-type reads Mesa converts through bytes (its ubyte
// intermediate): the unsigned normalized colour formats of up to 16 bits.
bool viaBytesFormat(TexelFormat f) {
  switch (f) {
    case TexelFormat::RGBA8: case TexelFormat::RGBX8: case TexelFormat::L8: case TexelFormat::A8:
    case TexelFormat::I8: case TexelFormat::L8A8: case TexelFormat::L4A4: case TexelFormat::RGBA4:
    case TexelFormat::RGBX4: case TexelFormat::RGB5X1: case TexelFormat::RGB5A1: case TexelFormat::R5G6B5:
    case TexelFormat::R3G3B2: case TexelFormat::RGB10X2: case TexelFormat::RGB10A2: case TexelFormat::RGBA16:
    case TexelFormat::RGBX16: case TexelFormat::L16: case TexelFormat::A16: case TexelFormat::I16:
    case TexelFormat::L16A16:
      return true;
    default:
      return false;
  }
}

// (Mesa gives it for a depth-stencil texture).
void packDepthStencil(const uint8_t* texel, GLenum format, GLenum type, uint8_t* out) {
  const uint32_t depth24 = storedChannel(TexelFormat::Z24S8, texel, 0), stencil = texelStencil(texel);
  if (format == GL_STENCIL_INDEX) {
    if (type == GL_FLOAT) {
      const float f = static_cast<float>(stencil);
      uint32_t v;
      std::memcpy(&v, &f, 4);
      writeElement(out, 4, v);
    } else if (type == GL_HALF_FLOAT_ARB) {
      writeElement(out, 2, floatToHalfNearest(static_cast<float>(stencil)));
    } else {
      writeElement(out, elementBytes(type), stencil);
    }
    return;
  }
  if (type == GL_UNSIGNED_INT_24_8) {
    writeElement(out, 4, depth24 << 8 | stencil);
    return;
  }
  const float depth = unormToFloat(depth24, 24);
  uint32_t v;
  std::memcpy(&v, &depth, 4);
  writeElement(out, 4, v);
  writeElement(out + 4, 4, stencil);
}

}  // namespace

// One pixel's components (in the format's order) as a packed element
// (table 3.8), rounded as Mesa packs them (measured; reference/MESA_FACTS.md
// "Packed pixel types"): 8-bit fields take the byte `b`; with `viaBytes`
// (Mesa's ubyte intermediate) narrower fields the byte rescaled and rounded,
// and with `replicateBytes` (an RGBA8 source) 10-bit fields the byte with its
// high bits replicated below; the rest from the float `c` (clamped to [0, 1])
// as (uint)(c * (2^n - 1) + 0.5) in float.
uint32_t packElement(const Packed& packed, const float c[4], const uint8_t b[4], bool viaBytes,
                     bool replicateBytes) {
  uint32_t v = 0;
  int used = 0;
  const int total = packed.bytes * 8;
  for (int n = 0; n < packed.fields; ++n) {
    const int w = packed.width[n];
    const int shift = packed.reversed ? used : total - used - w;
    used += w;
    const uint32_t max = (1u << w) - 1;
    uint32_t field;
    if (w == 8) {
      field = b[n];
    } else if (w < 8 && viaBytes) {
      field = (b[n] * max + 127) / 255;  // never a tie: 255 is odd
    } else if (w == 10 && replicateBytes) {
      field = (uint32_t{b[n]} << 2) | (b[n] >> 6);
    } else {
      field = static_cast<uint32_t>(clamp01(c[n]) * static_cast<float>(max) + 0.5f);
    }
    v |= field << shift;
  }
  return v;
}

void packImage(const TextureImage& image, const ClientLayout& layout, GLenum format, GLenum type,
               uint8_t* pixels) {
  const int components = componentsOf(format);
  const Packed packed = packedType(type);
  const int bytes = elementBytes(type);
  for (int k = 0; k < image.depth; ++k) {
    for (int j = 0; j < image.height; ++j) {
      const int clientRow = layout.invertRows ? image.height - 1 - j : j;
      uint8_t* row = pixels + layout.start + size_t(k) * layout.imageStride + size_t(clientRow) * layout.rowStride;
      for (int i = 0; i < image.width; ++i) {
        const uint8_t* texel = image.texel(i, j, k);
        uint8_t* group = row + size_t(i) * layout.groupBytes;
        if (format == GL_DEPTH_STENCIL || format == GL_STENCIL_INDEX) {  // a Z24S8 image (glGetTexImage checks)
          packDepthStencil(texel, format, type, group);
          continue;
        }
        float rgba[4];
        texelToRGBA(image.format, texel, rgba);
        float c[4] = {0, 0, 0, 0};
        switch (format) {
          case GL_RED:
          case GL_LUMINANCE:
          case GL_DEPTH_COMPONENT: c[0] = rgba[0]; break;
          case GL_GREEN: c[0] = rgba[1]; break;
          case GL_BLUE: c[0] = rgba[2]; break;
          case GL_ALPHA: c[0] = rgba[3]; break;
          case GL_LUMINANCE_ALPHA: c[0] = rgba[0], c[1] = rgba[3]; break;
          case GL_RGB: c[0] = rgba[0], c[1] = rgba[1], c[2] = rgba[2]; break;
          case GL_BGR: c[0] = rgba[2], c[1] = rgba[1], c[2] = rgba[0]; break;
          case GL_RGBA: c[0] = rgba[0], c[1] = rgba[1], c[2] = rgba[2], c[3] = rgba[3]; break;
          case GL_BGRA: c[0] = rgba[2], c[1] = rgba[1], c[2] = rgba[0], c[3] = rgba[3]; break;
        }
        uint8_t* out = row + size_t(i) * layout.groupBytes;
        if (packed.bytes) {
          // As Mesa's _mesa_format_convert packs them (measured; MESA_FACTS.md
          // "Packed pixel types"): from RGBA8, the bytes (10-bit fields the
          // byte with its high bits replicated below); from other unorm
          // formats of at most 16 bits, fields of at most 8 bits through the
          // bytes Mesa unpacks (n-bit channels bit-replicated, 16-bit ones
          // rounded), wider ones through the float; the rest through the float.
          const bool viaBytes = viaBytesFormat(image.format);
          uint8_t rgbaBytes[4] = {0, 0, 0, 0};
          if (viaBytes) {
            const TexelFormatInfo& info = texelFormatInfo(image.format);
            if (info.fitsUnorm8) {
              decodeTexelUnorm8(image.format, texel, rgbaBytes);
              // Luminance and intensity to red alone, as texelToRGBA maps them (table 6.1).
              if (info.baseFormat == GL_LUMINANCE || info.baseFormat == GL_INTENSITY ||
                  info.baseFormat == GL_LUMINANCE_ALPHA) {
                rgbaBytes[1] = rgbaBytes[2] = 0;
                if (info.baseFormat != GL_LUMINANCE_ALPHA) rgbaBytes[3] = 255;
              }
            } else {
              for (int n = 0; n < 4; ++n)
                rgbaBytes[n] = static_cast<uint8_t>(std::nearbyint(clamp01(rgba[n]) * 255.0f));
            }
          }
          // Without the bytes, 8-bit fields take the float's rounding.
          if (!viaBytes)
            for (int n = 0; n < 4; ++n)
              rgbaBytes[n] = static_cast<uint8_t>(clamp01(rgba[n]) * 255.0f + 0.5f);
          const bool bgra = format == GL_BGRA;
          const uint8_t b[4] = {bgra ? rgbaBytes[2] : rgbaBytes[0], rgbaBytes[1], bgra ? rgbaBytes[0] : rgbaBytes[2],
                                rgbaBytes[3]};
          const uint32_t v = packElement(packed, c, b, viaBytes, viaBytes && image.format == TexelFormat::RGBA8);
          writeElement(out, packed.bytes, v);
        } else if (format == GL_DEPTH_COMPONENT && (type == GL_UNSIGNED_INT || type == GL_INT)) {
          // Mesa packs depth as (GLuint)(z * 4294967295.0) and (GLint)(z *
          // 2147483647.0) in double, truncated (_mesa_pack_depth_span,
          // FLOAT_TO_UINT): a 24-bit 0x800000 (z 0.50000006 in float) reads
          // 0x800000ff, where rounding the double would give 0x80000100.
          const double z = clamp01(c[0]);
          const uint32_t v = type == GL_UNSIGNED_INT ? static_cast<uint32_t>(z * 4294967295.0)
                                                     : static_cast<uint32_t>(static_cast<int32_t>(z * 2147483647.0));
          writeElement(out, bytes, v);
        } else {
          for (int n = 0; n < components; ++n)
            writeElement(out + n * bytes, bytes, floatToElement(c[n], type));
        }
      }
    }
  }
}

}  // namespace glfixed::texture
