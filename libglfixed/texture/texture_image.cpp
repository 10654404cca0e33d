#include "texture/texture_image.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "texture/unpack.h"

namespace glfixed::texture {

size_t llvmpipeImageBytes(TexelFormat format, int width, int height, int depth) {
  const TexelFormatInfo& info = texelFormatInfo(format);
  int bits = 0;
  for (int c = 0; c < info.channels; ++c) bits += info.bits[c];
  size_t bytes = 1;
  while (bytes * 8 < static_cast<size_t>(bits)) bytes *= 2;  // R8G8B8X8, R16G16B16X16, ...
  return bytes * size_t(width) * size_t(height) * size_t(depth);
}

bool defineImage(TextureImage& image, GLint internalFormat, TexelFormat format, int width, int height,
                 int depth) {
  image = TextureImage();
  if (width <= 0 || height <= 0 || depth <= 0) return true;
  const size_t texelBytes = static_cast<size_t>(texelFormatInfo(format).bytesPerTexel);
  const size_t rowStride = texelBytes * size_t(width);
  const size_t imageStride = rowStride * size_t(height);
  try {
    image.texels.resize(imageStride * size_t(depth));
  } catch (const std::bad_alloc&) {
    image = TextureImage();
    return false;
  }
  image.width = width;
  image.height = height;
  image.depth = depth;
  image.internalFormat = internalFormat;
  image.format = format;
  image.rowStride = rowStride;
  image.imageStride = imageStride;
  return true;
}

void defineProxyImage(TextureImage& image, GLint internalFormat, TexelFormat format, int width, int height,
                      int depth) {
  image = TextureImage();
  if (width <= 0 || height <= 0 || depth <= 0) return;
  image.width = width;
  image.height = height;
  image.depth = depth;
  image.internalFormat = internalFormat;
  image.format = format;
}

namespace {

// One axis of a linear sample at a destination texel's centre: the two
// source texels and the weight of the second (clamped to the edge).
struct Tap {
  int i0, i1;
  float frac;
  int frac8;  // the weight in 8 bits, as llvmpipe's 8-bit filter takes it
};
Tap tapFor(int dst, int srcSize, int dstSize) {
  const float u =
      (static_cast<float>(dst) + 0.5f) * static_cast<float>(srcSize) / static_cast<float>(dstSize) - 0.5f;
  const float fl = std::floor(u);
  Tap t;
  t.frac = u - fl;
  t.frac8 = static_cast<int>(t.frac * 256.0f);
  const int i = static_cast<int>(fl);
  t.i0 = std::clamp(i, 0, srcSize - 1);
  t.i1 = std::clamp(i + 1, 0, srcSize - 1);
  return t;
}

// llvmpipe's 8-bit lerp: a + ((b - a) * w + 128) >> 8, w in 1/256ths
// (probed: a 2x2 box gives ((a + b + 1) >> 1 + (c + d + 1) >> 1 + 1) >> 1).
int lerp8(int a, int b, int w) { return a + (((b - a) * w + 128) >> 8); }

void downsample(const TextureImage& src, TextureImage& dst) {
  const TexelFormatInfo& info = texelFormatInfo(src.format);
  for (int k = 0; k < dst.depth; ++k) {
    const Tap tz = tapFor(k, src.depth, dst.depth);
    for (int j = 0; j < dst.height; ++j) {
      const Tap ty = tapFor(j, src.height, dst.height);
      for (int i = 0; i < dst.width; ++i) {
        const Tap tx = tapFor(i, src.width, dst.width);
        float rgba[4];
        if (info.fitsUnorm8) {
          int z[2][4];
          for (int zi = 0; zi < 2; ++zi) {
            const int sz = zi ? tz.i1 : tz.i0;
            int y[2][4];
            for (int yi = 0; yi < 2; ++yi) {
              const int sy = yi ? ty.i1 : ty.i0;
              uint8_t a[4], b[4];
              decodeTexelUnorm8(src.format, src.texel(tx.i0, sy, sz), a);
              decodeTexelUnorm8(src.format, src.texel(tx.i1, sy, sz), b);
              for (int c = 0; c < 4; ++c) y[yi][c] = lerp8(a[c], b[c], tx.frac8);
            }
            for (int c = 0; c < 4; ++c) z[zi][c] = lerp8(y[0][c], y[1][c], ty.frac8);
          }
          for (int c = 0; c < 4; ++c)
            rgba[c] = static_cast<float>(lerp8(z[0][c], z[1][c], tz.frac8)) / 255.0f;
        } else {
          float z[2][4];
          for (int zi = 0; zi < 2; ++zi) {
            const int sz = zi ? tz.i1 : tz.i0;
            float y[2][4];
            for (int yi = 0; yi < 2; ++yi) {
              const int sy = yi ? ty.i1 : ty.i0;
              float a[4], b[4];
              decodeTexelFloat(src.format, src.texel(tx.i0, sy, sz), a);
              decodeTexelFloat(src.format, src.texel(tx.i1, sy, sz), b);
              for (int c = 0; c < 4; ++c) y[yi][c] = a[c] + (b[c] - a[c]) * tx.frac;
            }
            for (int c = 0; c < 4; ++c) z[zi][c] = y[0][c] + (y[1][c] - y[0][c]) * ty.frac;
          }
          for (int c = 0; c < 4; ++c) rgba[c] = z[0][c] + (z[1][c] - z[0][c]) * tz.frac;
        }
        // decode gave the base format's RGBA (L in R, G and B; I in all):
        // storeTexel takes R for L and I, A for alpha.
        storeTexel(dst.format, rgba,
                   dst.texels.data() + size_t(k) * dst.imageStride + size_t(j) * dst.rowStride +
                       size_t(i) * info.bytesPerTexel);
      }
    }
  }
}

}  // namespace

bool generateMipmaps(TextureObject& object, int face, int baseLevel, int maxLevels) {
  if (baseLevel < 0 || baseLevel >= maxLevels) return true;
  const int last = std::min(maxLevels - 1, object.params.maxLevel);
  for (int level = baseLevel + 1; level <= last; ++level) {
    const TextureImage& src = object.face[face][level - 1];
    if (!src.defined() || (src.width == 1 && src.height == 1 && src.depth == 1)) break;
    TextureImage& dst = object.face[face][level];
    const bool is3D = object.target == GL_TEXTURE_3D;
    if (!defineImage(dst, src.internalFormat, src.format, std::max(1, src.width / 2),
                     std::max(1, src.height / 2), is3D ? std::max(1, src.depth / 2) : 1))
      return false;
    downsample(src, dst);
  }
  return true;
}

}  // namespace glfixed::texture
