#include "framebuffer/read_pixels.h"

#include "framebuffer/stencil_index.h"
#include "texture/unpack.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

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

namespace glfixed {

void clearDepth(Framebuffer& fb, uint32_t value, const PixelBox& box) {
  for (int y = std::max(box.y0, 0); y < std::min(box.y1, fb.depth.height()); ++y)
    for (int x = std::max(box.x0, 0); x < std::min(box.x1, fb.depth.width()); ++x) fb.depth.set(x, y, value);
}

PixelBox scissoredBox(const Framebuffer& fb, const ScissorAttrib& s) {
  PixelBox box{0, 0, fb.width(), fb.height()};
  if (s.test) {
    box.x0 = std::max(box.x0, s.x);
    box.y0 = std::max(box.y0, s.y);
    box.x1 = static_cast<int>(std::min<long long>(box.x1, static_cast<long long>(s.x) + s.width));
    box.y1 = static_cast<int>(std::min<long long>(box.y1, static_cast<long long>(s.y) + s.height));
  }
  return box;
}

void clearStencil(Framebuffer& fb, uint32_t value, uint32_t writeMask, const PixelBox& box) {
  for (int y = std::max(box.y0, 0); y < std::min(box.y1, fb.depth.height()); ++y)
    for (int x = std::max(box.x0, 0); x < std::min(box.x1, fb.depth.width()); ++x)
      fb.depth.setStencil(x, y, value, writeMask);
}

void clearColor(const ColorBuffer& c, const ColorBufferAttrib& cb, const PixelBox& box) {
  if (!c.pixels) return;
  if (c.channels != ChannelType::kUnorm8) {
    // 5-6-5, 16-bit and float buffers: from the float colour, rounded to the
    // channel's size (a float buffer keeps values outside [0, 1]).
    const bool* mask = cb.writeMask.data();
    const float value[4] = {cb.clearColorUnclamped.r, cb.clearColorUnclamped.g, cb.clearColorUnclamped.b,
                            cb.clearColorUnclamped.a};
    // Mesa clears a scissored part of the buffer, or some of its channels,
    // by drawing a quad (st_Clear): its colour is then stored as a
    // fragment's, which differs from the clear's rounding on 16-bit and
    // 10-bit channels (probed: 1-pixel scissored clears of RGBA16 round to
    // nearest even, of RGB10_A2 truncate from 16 bits).
    const bool wholeBuffer = box.x0 <= 0 && box.y0 <= 0 && box.x1 >= c.width && box.y1 >= c.height;
    bool allChannels = true;
    for (int k = 0; k < 4; ++k) allChannels = allChannels && (mask[k] || c.channelBits(k) == 0);
    const bool asFragment = (!wholeBuffer || !allChannels) &&
                            (c.channels == ChannelType::kUnorm16 || c.channels == ChannelType::kUnormWideBits);
    for (int y = std::max(box.y0, 0); y < std::min(box.y1, c.height); ++y)
      for (int x = std::max(box.x0, 0); x < std::min(box.x1, c.width); ++x)
        c.writeFloat(x, y, value, mask, !asFragment);
    return;
  }
  uint8_t value[4];
  for (int i = 0; i < 4; ++i) value[i] = floatToUnorm8(cb.clearColor[i]);
  const bool allChannels = cb.writeMask[0] && cb.writeMask[1] && cb.writeMask[2] && cb.writeMask[3];
  const int x0 = std::max(box.x0, 0), x1 = std::min(box.x1, c.width);
  if (allChannels && c.bytesPerPixel == 4 && x1 > x0) {
    // The common clear: one row of the pixel built once, copied into every
    // row (an unused fourth byte is set too; nothing reads it).
    uint8_t pixel[4] = {255, 255, 255, 255};
    pixel[c.red] = value[0];
    pixel[c.green] = value[1];
    pixel[c.blue] = value[2];
    if (c.alpha >= 0) pixel[c.alpha] = value[3];
    std::vector<uint8_t> row(static_cast<size_t>(x1 - x0) * 4);
    for (size_t i = 0; i < row.size(); i += 4) std::memcpy(&row[i], pixel, 4);
    for (int y = std::max(box.y0, 0); y < std::min(box.y1, c.height); ++y)
      std::memcpy(c.pixel(x0, y), row.data(), row.size());
    return;
  }
  for (int y = std::max(box.y0, 0); y < std::min(box.y1, c.height); ++y) {
    for (int x = std::max(box.x0, 0); x < std::min(box.x1, c.width); ++x) {
      if (allChannels) {
        c.write(x, y, value);
        continue;
      }
      uint8_t old[4];
      c.read(x, y, old);
      for (int i = 0; i < 4; ++i)
        if (cb.writeMask[i]) old[i] = value[i];
      c.write(x, y, old);
    }
  }
}

namespace {

int componentsOf(GLenum format) {
  switch (format) {
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: case GL_DEPTH_COMPONENT:
    case GL_STENCIL_INDEX: case GL_DEPTH_STENCIL:
      return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB: case GL_BGR: return 3;
    case GL_RGBA: case GL_BGRA: return 4;
    default: return 0;
  }
}

int bytesOf(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
  }
}

// A packed colour type (table 3.8; texture/unpack.h).
bool isPacked(GLenum type) { return texture::packedType(type).bytes > 0; }

// EXT_packed_depth_stencil and ARB_depth_buffer_float's depth-stencil pixels.
bool isDepthStencilType(GLenum type) {
  return type == GL_UNSIGNED_INT_24_8 || type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
}

bool isKnownType(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_UNSIGNED_INT:
    case GL_INT: case GL_FLOAT: case GL_BITMAP:
    case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV: case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV: case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV: case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV: case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_24_8: case GL_FLOAT_32_UNSIGNED_INT_24_8_REV:
      return true;
    default:
      return false;
  }
}

bool isKnownFormat(GLenum format) {
  return componentsOf(format) > 0 || format == GL_COLOR_INDEX;
}

// The bytes of one pixel of a depth-stencil type.
int depthStencilBytes(GLenum type) { return type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV ? 8 : 4; }

// A stencil index stored as `type` (Mesa's packing: GL_BYTE keeps the low 7 bits).
void storeStencil(uint8_t* dst, GLenum type, uint32_t s) {
  switch (type) {
    case GL_UNSIGNED_BYTE: *dst = static_cast<uint8_t>(s); break;
    case GL_BYTE: *dst = static_cast<uint8_t>(s & 0x7f); break;
    case GL_UNSIGNED_SHORT: case GL_SHORT: {
      const uint16_t v = static_cast<uint16_t>(s);
      std::memcpy(dst, &v, 2);
      break;
    }
    case GL_UNSIGNED_INT: case GL_INT: std::memcpy(dst, &s, 4); break;
    case GL_FLOAT: {
      const float f = static_cast<float>(s);
      std::memcpy(dst, &f, 4);
      break;
    }
  }
}

// Stores one component, converted from [0,1] float (or the raw unsigned
// value for depth) per GL 2.1 table 4.7.
void storeComponent(uint8_t* dst, GLenum type, float f) {
  switch (type) {
    case GL_UNSIGNED_BYTE: *dst = static_cast<uint8_t>(std::nearbyint(f * 255.0f)); break;
    case GL_BYTE: *reinterpret_cast<int8_t*>(dst) = static_cast<int8_t>(std::nearbyint((f * 255.0f - 1.0f) / 2)); break;
    case GL_UNSIGNED_SHORT: {
      uint16_t v = static_cast<uint16_t>(std::nearbyint(f * 65535.0f));
      std::memcpy(dst, &v, 2);
      break;
    }
    case GL_SHORT: {
      int16_t v = static_cast<int16_t>(std::nearbyint((f * 65535.0f - 1.0f) / 2));
      std::memcpy(dst, &v, 2);
      break;
    }
    case GL_UNSIGNED_INT: {
      uint32_t v = static_cast<uint32_t>(std::nearbyint(double(f) * 4294967295.0));
      std::memcpy(dst, &v, 4);
      break;
    }
    case GL_INT: {
      int32_t v = static_cast<int32_t>(std::nearbyint((double(f) * 4294967295.0 - 1.0) / 2));
      std::memcpy(dst, &v, 4);
      break;
    }
    case GL_FLOAT: std::memcpy(dst, &f, 4); break;
  }
}

// One colour component as Mesa packs it (measured; reference/MESA_FACTS.md
// "Pixel maps and pixel transfer"): signed types c * (2^(b-1) - 1) rounded
// (the GL 3 rule); 32-bit types from a byte of the buffer exactly (the byte
// replicated, or b / 255 * INT_MAX rounded), and from a float (pixel transfer
// applied) in float precision. `byte` is the buffer's byte, or -1.
void storeColorComponent(uint8_t* dst, GLenum type, float f, int byte) {
  switch (type) {
    case GL_BYTE: *reinterpret_cast<int8_t*>(dst) = static_cast<int8_t>(std::lround(double(f) * 127.0)); return;
    case GL_SHORT: {
      const int16_t v = static_cast<int16_t>(std::lround(double(f) * 32767.0));
      std::memcpy(dst, &v, 2);
      return;
    }
    case GL_UNSIGNED_INT: {
      uint32_t v;
      if (byte >= 0) {
        v = static_cast<uint32_t>(byte) * 0x01010101u;
      } else {
        const float x = f * 4294967295.0f;
        v = x >= 4294967295.0f ? 0xffffffffu : x > 0.0f ? static_cast<uint32_t>(x) : 0u;
      }
      std::memcpy(dst, &v, 4);
      return;
    }
    case GL_INT: {
      int32_t v;
      if (byte >= 0) {
        v = static_cast<int32_t>(std::lround(byte / 255.0 * 2147483647.0));
      } else {
        const float x = f * 2147483647.0f;
        v = x >= 2147483647.0f ? 2147483647 : x <= -2147483647.0f ? -2147483647 : static_cast<int32_t>(x);
      }
      std::memcpy(dst, &v, 4);
      return;
    }
    default: storeComponent(dst, type, f); return;
  }
}

}  // namespace

size_t packedImageBytes(const PixelStoreAttrib& pack, GLsizei width, GLsizei height, GLenum format, GLenum type) {
  if (width <= 0 || height <= 0 || !isKnownFormat(format) || !isKnownType(type)) return 0;
  const int componentBytes = isPacked(type) || isDepthStencilType(type) ? 1 : bytesOf(type);
  const size_t pixelBytes = isPacked(type)            ? texture::packedType(type).bytes
                            : isDepthStencilType(type) ? depthStencilBytes(type)
                                                       : static_cast<size_t>(componentsOf(format)) * componentBytes;
  const size_t rowPixels = pack.packRowLength > 0 ? pack.packRowLength : width;
  size_t rowBytes = rowPixels * pixelBytes;
  const size_t align = static_cast<size_t>(pack.packAlignment);
  if (componentBytes < static_cast<int>(align)) rowBytes = (rowBytes + align - 1) / align * align;
  return (static_cast<size_t>(pack.packSkipRows) + height - 1) * rowBytes +
         (static_cast<size_t>(pack.packSkipPixels) + width) * pixelBytes;
}

GLenum readPixels(const Framebuffer& fb, const PixelStoreAttrib& pack, GLint x, GLint y, GLsizei width,
                  GLsizei height, GLenum format, GLenum type, void* pixels, const PixelModeAttrib& transfer,
                  const PixelMaps* maps) {
  if (!isKnownFormat(format) || !isKnownType(type)) return GL_INVALID_ENUM;
  // EXT_packed_depth_stencil: GL_DEPTH_STENCIL only with its types (else an
  // invalid enum), its types only with it (else an invalid operation).
  if (format == GL_DEPTH_STENCIL && !isDepthStencilType(type)) return GL_INVALID_ENUM;
  if (format != GL_DEPTH_STENCIL && isDepthStencilType(type)) return GL_INVALID_OPERATION;
  if (format == GL_COLOR_INDEX) return GL_INVALID_OPERATION;  // RGBA only
  const bool stencil = format == GL_STENCIL_INDEX, depthStencil = format == GL_DEPTH_STENCIL;
  if ((stencil || depthStencil) && fb.depth.stencilBits() == 0) return GL_INVALID_OPERATION;
  if ((format == GL_DEPTH_COMPONENT || depthStencil) && fb.depth.bits() == 0) return GL_INVALID_OPERATION;
  // §3.6.4: a packed type only with a format of its component count (3: GL_RGB, 4: GL_RGBA or GL_BGRA).
  const texture::Packed packed = texture::packedType(type);
  if (packed.bytes && packed.fields == 3 && format != GL_RGB) return GL_INVALID_OPERATION;
  if (packed.bytes && packed.fields == 4 && format != GL_RGBA && format != GL_BGRA) return GL_INVALID_OPERATION;
  if (!packed.bytes && !isDepthStencilType(type) && bytesOf(type) == 0) return GL_INVALID_OPERATION;  // GL_BITMAP
  const bool depth =
      format == GL_DEPTH_COMPONENT || stencil || depthStencil;  // read from the depth-stencil buffer
  // Mesa: colour from a read buffer of GL_NONE is an invalid operation.
  if (!depth && fb.hasSurface() && !fb.read.pixels) return GL_INVALID_OPERATION;
  if (!fb.hasSurface() || !pixels || width == 0 || height == 0) return GL_NO_ERROR;

  const int components = componentsOf(format);
  const bool colorTransfer =
      transfer.scale != glm::vec4(1) || transfer.bias != glm::vec4(0) || (transfer.mapColor && maps);
  const int componentBytes = packed.bytes || isDepthStencilType(type) ? 1 : bytesOf(type);
  const int pixelBytes = packed.bytes               ? packed.bytes
                         : isDepthStencilType(type) ? depthStencilBytes(type)
                                                    : components * componentBytes;
  const int rowPixels = pack.packRowLength > 0 ? pack.packRowLength : width;
  // GL 2.1 §4.3.2 / §3.6.4: rows are padded to the pack alignment.
  size_t rowBytes = static_cast<size_t>(rowPixels) * pixelBytes;
  const size_t align = static_cast<size_t>(pack.packAlignment);
  if (componentBytes < static_cast<int>(align)) rowBytes = (rowBytes + align - 1) / align * align;
  uint8_t* base = static_cast<uint8_t*>(pixels) + pack.packSkipRows * rowBytes +
                  static_cast<size_t>(pack.packSkipPixels) * pixelBytes;

  // Only the rows and columns inside the framebuffer are read, the rest of
  // `pixels` is left alone. In 64 bits: x + col can pass INT_MAX.
  const auto inside = [](GLint origin, GLsizei count, int size, int& first, int& last) {
    first = static_cast<int>(std::clamp<int64_t>(-int64_t{origin}, 0, count));
    last = static_cast<int>(std::clamp<int64_t>(int64_t{size} - origin, first, count));
  };
  // GL 2.1 §3.6.5 on depth reads: the stored depth as a float, scaled and
  // biased, clamped to [0, 1]; Mesa leaves the identity to its plain paths.
  const bool depthTransfer = transfer.depthScale != 1.0f || transfer.depthBias != 0.0f;
  const auto scaledDepth = [&](uint32_t d) {
    const float z =
        static_cast<float>(d * (1.0 / fb.depth.maxValue())) * transfer.depthScale + transfer.depthBias;
    return z > 0.0f ? (z < 1.0f ? z : 1.0f) : 0.0f;  // NaN: 0
  };
  int row0, row1, col0, col1;
  // The read buffer may be another surface's (glXMakeContextCurrent).
  inside(y, height, depth ? fb.depth.height() : fb.read.height, row0, row1);
  inside(x, width, depth ? fb.depth.width() : fb.read.width, col0, col1);
  for (int row = row0; row < row1; ++row) {
    const int wy = y + row;
    uint8_t* dstRow = base + (pack.packInvert ? height - 1 - row : row) * rowBytes;  // GL_MESA_pack_invert
    for (int col = col0; col < col1; ++col) {
      const int wx = x + col;
      uint8_t* dst = dstRow + static_cast<size_t>(col) * pixelBytes;
      if (stencil) {
        // GL 2.1 §4.3.2: the index through the pixel transfer, kept to 8 bits.
        storeStencil(dst, type, transferStencilIndex(transfer, maps, fb.depth.getStencil(wx, wy)));
        continue;
      }
      if (depthStencil) {
        // The stencil through the index transfer as for GL_STENCIL_INDEX (measured).
        const uint32_t d = fb.depth.get(wx, wy),
                       s = transferStencilIndex(transfer, maps, fb.depth.getStencil(wx, wy));
        if (type == GL_UNSIGNED_INT_24_8) {
          // Scaled: truncated to 24 bits (measured).
          const uint32_t z = depthTransfer ? static_cast<uint32_t>(double(scaledDepth(d)) * 16777215.0) : d;
          const uint32_t v = (z << 8) | s;
          std::memcpy(dst, &v, 4);
        } else {  // a float depth, then the stencil in the low byte of a word
          const float z =
              depthTransfer ? scaledDepth(d) : static_cast<float>(d * (1.0 / fb.depth.maxValue()));
          std::memcpy(dst, &z, 4);
          std::memcpy(dst + 4, &s, 4);
        }
        continue;
      }
      if (format == GL_DEPTH_COMPONENT) {
        const uint32_t d = fb.depth.get(wx, wy);
        const int bits = fb.depth.bits();
        if (depthTransfer) {
          // Mesa's float-to-type macros (measured): GL_UNSIGNED_INT and the
          // byte types truncated, GL_BYTE and GL_SHORT as (trunc(max z) - 1) / 2;
          // GL_UNSIGNED_SHORT, GL_INT and GL_FLOAT as for colours.
          const float z = scaledDepth(d);
          if (type == GL_UNSIGNED_INT) {
            const uint32_t v = static_cast<uint32_t>(double(z) * 4294967295.0);
            std::memcpy(dst, &v, 4);
          } else if (type == GL_UNSIGNED_BYTE) {
            *dst = static_cast<uint8_t>(z * 255.0f);
          } else if (type == GL_BYTE) {
            *reinterpret_cast<int8_t*>(dst) = static_cast<int8_t>((static_cast<int>(255.0f * z) - 1) / 2);
          } else if (type == GL_SHORT) {
            const int16_t v = static_cast<int16_t>((static_cast<int>(65535.0f * z) - 1) / 2);
            std::memcpy(dst, &v, 2);
          } else {
            storeComponent(dst, type, z);
          }
        } else if (type == GL_UNSIGNED_INT) {
          // Replicate the high bits into the low ones: 1.0 reads as 0xffffffff.
          uint32_t v = bits == 16 ? (d << 16) | d : (d << 8) | (d >> 16);
          std::memcpy(dst, &v, 4);
        } else {
          storeComponent(dst, type, static_cast<float>(d * (1.0 / fb.depth.maxValue())));
        }
        continue;
      }
      uint8_t rgba[4];
      float f[4];
      const bool bytes = fb.read.channels == ChannelType::kUnorm8;
      if (bytes) {
        fb.read.read(wx, wy, rgba);
        for (int i = 0; i < 4; ++i) f[i] = rgba[i] * (1.0f / 255.0f);
      } else {
        // 5-6-5, 16-bit and float buffers: their values as floats, clamped
        // (Mesa's OSMesa buffers are not in float mode: GL_CLAMP_READ_COLOR's
        // GL_FIXED_ONLY clamps them), then converted to the type.
        // 5-6-5 gives bytes by bit replication (ColorBuffer::read), as Mesa's
        // unpack to 8 bits.
        // A framebuffer object's float attachment is in float mode: its
        // floats are read unclamped, the other types from the clamped value.
        fb.read.readFloat(wx, wy, f);
        for (int i = 0; i < 4; ++i) {
          const float clamped = f[i] > 0.0f ? (f[i] < 1.0f ? f[i] : 1.0f) : 0.0f;
          if (!(fb.read.floatMode && type == GL_FLOAT)) f[i] = clamped;
          rgba[i] = static_cast<uint8_t>(std::nearbyint(clamped * 255.0f));
        }
        if (fb.read.channels == ChannelType::kRGB565 || fb.read.channels == ChannelType::kUnormBits)
          fb.read.read(wx, wy, rgba);
      }
      if (colorTransfer) {  // §3.6.5: scale and bias, then the colour maps
        for (int i = 0; i < 4; ++i) {
          f[i] = f[i] * transfer.scale[i] + transfer.bias[i];
          if (transfer.mapColor && maps) f[i] = (*maps)[GL_PIXEL_MAP_R_TO_R + i].atColor(f[i]);
          // Clamped to the type's range: [0, 1], [-1, 1] for signed types, not for floats.
          const float low = type == GL_BYTE || type == GL_SHORT || type == GL_INT ? -1.0f : 0.0f;
          if (type != GL_FLOAT) f[i] = f[i] > low ? (f[i] < 1.0f ? f[i] : 1.0f) : low;
          rgba[i] = static_cast<uint8_t>(std::nearbyint(std::clamp(f[i], 0.0f, 1.0f) * 255.0f));
        }
      }
      if (packed.bytes) {
        const bool bgra = format == GL_BGRA;
        const float c[4] = {bgra ? f[2] : f[0], f[1], bgra ? f[0] : f[2], f[3]};
        const uint8_t b[4] = {bgra ? rgba[2] : rgba[0], rgba[1], bgra ? rgba[0] : rgba[2], rgba[3]};
        // Mesa's _mesa_format_convert: from an RGBA8 buffer (in that byte
        // order) it packs the bytes; from the others, for types of at most 8
        // bits a channel, through bytes as it unpacks them, else through
        // floats; float and half-float buffers, and anything after pixel
        // transfer, through floats.
        const ColorBuffer& rb = fb.read;
        const bool rgba8 = bytes && rb.red == 0 && rb.green == 1 && rb.blue == 2 && rb.alpha == 3;
        const bool viaBytes =
            !colorTransfer && rb.channels != ChannelType::kFloat32 && rb.channels != ChannelType::kFloat16;
        const uint32_t v = texture::packElement(packed, c, b, viaBytes, viaBytes && rgba8);
        // In native byte order, as Mesa writes it.
        if (packed.bytes == 1) {
          *dst = static_cast<uint8_t>(v);
        } else if (packed.bytes == 2) {
          const uint16_t v16 = static_cast<uint16_t>(v);
          std::memcpy(dst, &v16, 2);
        } else {
          std::memcpy(dst, &v, 4);
        }
        continue;
      }
      if (type == GL_UNSIGNED_BYTE) {  // the common case: bytes as they are
        switch (format) {
          case GL_RGBA: std::memcpy(dst, rgba, 4); continue;
          case GL_RGB: std::memcpy(dst, rgba, 3); continue;
          case GL_BGRA: dst[0] = rgba[2]; dst[1] = rgba[1]; dst[2] = rgba[0]; dst[3] = rgba[3]; continue;
          case GL_BGR: dst[0] = rgba[2]; dst[1] = rgba[1]; dst[2] = rgba[0]; continue;
          default: break;
        }
      }
      float out[4];
      switch (format) {
        case GL_RED: out[0] = f[0]; break;
        case GL_GREEN: out[0] = f[1]; break;
        case GL_BLUE: out[0] = f[2]; break;
        case GL_ALPHA: out[0] = f[3]; break;
        case GL_LUMINANCE: out[0] = std::min(1.0f, f[0] + f[1] + f[2]); break;
        case GL_LUMINANCE_ALPHA: out[0] = std::min(1.0f, f[0] + f[1] + f[2]); out[1] = f[3]; break;
        case GL_RGB: out[0] = f[0]; out[1] = f[1]; out[2] = f[2]; break;
        case GL_BGR: out[0] = f[2]; out[1] = f[1]; out[2] = f[0]; break;
        case GL_RGBA: std::memcpy(out, f, sizeof f); break;
        case GL_BGRA: out[0] = f[2]; out[1] = f[1]; out[2] = f[0]; out[3] = f[3]; break;
      }
      // The buffer's byte of each component, for the exact 32-bit conversions.
      int outBytes[4] = {-1, -1, -1, -1};
      if (bytes && !colorTransfer) {
        switch (format) {
          case GL_RED: outBytes[0] = rgba[0]; break;
          case GL_GREEN: outBytes[0] = rgba[1]; break;
          case GL_BLUE: outBytes[0] = rgba[2]; break;
          case GL_ALPHA: outBytes[0] = rgba[3]; break;
          case GL_RGB: case GL_RGBA: for (int i = 0; i < 4; ++i) outBytes[i] = rgba[i]; break;
          case GL_BGR: case GL_BGRA:
            outBytes[0] = rgba[2]; outBytes[1] = rgba[1]; outBytes[2] = rgba[0]; outBytes[3] = rgba[3];
            break;
          default: break;  // luminance: a sum, through float
        }
      }
      // (16-bit and float buffers without transfer: as before, not measured.)
      for (int i = 0; i < components; ++i) {
        if (bytes || colorTransfer)
          storeColorComponent(dst + i * componentBytes, type, out[i], outBytes[i]);
        else
          storeComponent(dst + i * componentBytes, type, out[i]);
      }
    }
  }
  return GL_NO_ERROR;
}

}  // namespace glfixed
