// The span shader with AVX2 and FMA: eight fragments at a time, each lane
// computing exactly what shadeSpanScalar computes (the same operations in the
// same order, so the same bits; llvmpipe itself runs eight lanes with these
// instructions). Compiled for those instruction sets by function attribute
// and used only when the CPU has them.
#pragma GCC optimize("fp-contract=off")

#include <immintrin.h>

#include <cstring>

#include "raster/depth.h"
#include "raster/primitive_setup.h"

namespace glfixed::raster {

bool haveAvx2Fma() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

#define GLFIXED_AVX2 __attribute__((target("avx2,fma")))

namespace {

// fma(dady, py, fma(dadx, px, a0)), as Plane::at.
GLFIXED_AVX2 inline __m256 planeAt(const Plane& p, __m256 px, __m256 py) {
  return _mm256_fmadd_ps(_mm256_set1_ps(p.dady), py,
                         _mm256_fmadd_ps(_mm256_set1_ps(p.dadx), px, _mm256_set1_ps(p.a0)));
}

// depthToUnorm: min(z, 1), max(., 0) (minps/maxps return the second operand
// for NaN), then the 24- or 16-bit conversion.
GLFIXED_AVX2 inline __m256i depthToUnormX8(__m256 z, int bits) {
  z = _mm256_min_ps(z, _mm256_set1_ps(1.0f));
  z = _mm256_max_ps(z, _mm256_setzero_ps());
  if (bits == 16) {
    __m256 scaled = _mm256_mul_ps(z, _mm256_set1_ps(65535.0f / 65536.0f));
    __m256 biased = _mm256_add_ps(scaled, _mm256_set1_ps(128.0f));
    return _mm256_and_si256(_mm256_castps_si256(biased), _mm256_set1_epi32(0xffff));
  }
  return _mm256_cvtps_epi32(_mm256_mul_ps(z, _mm256_set1_ps(16777215.0f)));
}

// Values are below 2^24, so signed compares are unsigned compares.
GLFIXED_AVX2 inline __m256i depthPassesX8(GLenum func, __m256i z, __m256i stored) {
  const __m256i ones = _mm256_set1_epi32(-1);
  switch (func) {
    case GL_NEVER: return _mm256_setzero_si256();
    case GL_LESS: return _mm256_cmpgt_epi32(stored, z);
    case GL_EQUAL: return _mm256_cmpeq_epi32(z, stored);
    case GL_LEQUAL: return _mm256_xor_si256(_mm256_cmpgt_epi32(z, stored), ones);
    case GL_GREATER: return _mm256_cmpgt_epi32(z, stored);
    case GL_NOTEQUAL: return _mm256_xor_si256(_mm256_cmpeq_epi32(z, stored), ones);
    case GL_GEQUAL: return _mm256_xor_si256(_mm256_cmpgt_epi32(stored, z), ones);
    default: return ones;
  }
}

// colorToUnorm8: max(c, 0) (NaN -> 0), min(., 1), rint(c * 255).
GLFIXED_AVX2 inline __m256i colorToUnormX8(__m256 c) {
  c = _mm256_max_ps(c, _mm256_setzero_ps());
  c = _mm256_min_ps(c, _mm256_set1_ps(1.0f));
  return _mm256_cvtps_epi32(_mm256_mul_ps(c, _mm256_set1_ps(255.0f)));
}

}  // namespace

GLFIXED_AVX2 void shadePrimitiveAvx2(const PrimitiveSetup& t, const ShadeTarget& s) {
  // Locals, not reads through `s` and `t`: byte stores may alias anything, so
  // the compiler would reload every field after each store.
  const int height = s.height;
  const int depthWidth = s.depthWidth;
  const int depthBits = s.depthBits;
  const bool depthWrite = s.depthWrite;
  const GLenum depthFunc = s.depthFunc;
  const bool anyColor = s.anyColor;
  const bool secondary = s.secondary;
  const uint32_t* const stipplePattern = s.stipple;
  const bool flatPrimary = t.flatPrimary, flatSecondary = t.flatSecondary;
  // Every colour flat: the same bytes for every fragment (not under the
  // coverage of a smooth line, which changes alpha).
  const bool lineCoverage = t.lineCoverage;
  const bool isFlat = flatPrimary && (!secondary || flatSecondary) && !lineCoverage;
  const int bpp = s.bytesPerPixel;
  const int offset[4] = {s.red, s.green, s.blue, s.alpha};
  const bool colorWrite[4] = {s.colorWrite[0], s.colorWrite[1], s.colorWrite[2], s.colorWrite[3]};
  // A 4-byte pixel with every channel written: one 32-bit word a pixel.
  const bool packedStore = bpp == 4 && s.allColor && s.alpha >= 0;
  const Plane zPlane = t.z, wPlane = t.w;
  const __m256 zOffset = _mm256_set1_ps(t.zOffset);  // polygon offset, as the scalar shader
  const Plane* const planes = t.varying;

  const __m256 laneX = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i laneIndex = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const ColorBuffer& color = *s.color;
  uint32_t* const depth32Base = depthBits == 24 ? static_cast<uint32_t*>(s.depth) : nullptr;
  uint16_t* const depth16Base = depthBits == 16 ? static_cast<uint16_t*>(s.depth) : nullptr;

  // Flat colour: the same converted bytes for every fragment.
  __m256i flatBytes[4];
  if (isFlat) {
    float c[4] = {t.flat[0], t.flat[1], t.flat[2], t.flat[3]};
    if (secondary) {
      c[0] += t.flat[4];
      c[1] += t.flat[5];
      c[2] += t.flat[6];
    }
    for (int k = 0; k < 4; ++k) flatBytes[k] = _mm256_set1_epi32(colorToUnorm8(c[k]));
  }

  const int edgeCount = t.edgeCount;
  EdgeSpanStepper edges[kMaxEdges];
  for (int i = 0; i < edgeCount; ++i) edges[i] = EdgeSpanStepper(t.edge[i], t.y0);
  for (int py = t.y0; py <= t.y1; ++py) {
    int64_t spanLo = t.x0, spanHi = t.x1;
    for (int i = 0; i < edgeCount; ++i) edges[i].clip(spanLo, spanHi);
    for (int i = 0; i < edgeCount; ++i) edges[i].nextRow();
    if (spanLo > spanHi) continue;
    const int lo = static_cast<int>(spanLo), hi = static_cast<int>(spanHi);
    const int glY = height - 1 - py;
    const __m256 fpy = _mm256_set1_ps(static_cast<float>(py));
    uint8_t* const colorRow = color.pixel(0, glY);
    uint32_t* const depth32 = depth32Base ? depth32Base + size_t(glY) * depthWidth : nullptr;
    uint16_t* const depth16 = depth16Base ? depth16Base + size_t(glY) * depthWidth : nullptr;
    const uint32_t stipple = stipplePattern ? stippleRow(stipplePattern, glY) : ~0u;
    for (int x = lo; x <= hi; x += 8) {
      const int n = hi - x + 1 < 8 ? hi - x + 1 : 8;
      const bool full = n == 8;
      __m256i live = _mm256_cmpgt_epi32(_mm256_set1_epi32(n), laneIndex);
      if (stipple != ~0u) {  // polygon stipple: lane i is pixel x + i, bit 31 - (x + i) % 32
        const uint32_t rotated = (stipple << (x & 31)) | (x & 31 ? stipple >> (32 - (x & 31)) : 0u);
        const __m256i bits = _mm256_srlv_epi32(_mm256_set1_epi32(static_cast<int>(rotated)),
                                               _mm256_setr_epi32(31, 30, 29, 28, 27, 26, 25, 24));
        const __m256i one = _mm256_set1_epi32(1);
        live = _mm256_and_si256(live, _mm256_cmpeq_epi32(_mm256_and_si256(bits, one), one));
        if (_mm256_testz_si256(live, live)) continue;
      }
      const __m256 fpx = _mm256_add_ps(_mm256_set1_ps(static_cast<float>(x)), laneX);
      alignas(32) uint32_t lanes[8];

      if (depthBits) {
        const __m256i z = depthToUnormX8(_mm256_add_ps(planeAt(zPlane, fpx, fpy), zOffset), depthBits);
        __m256i stored;
        if (depth32) {
          if (full) {
            stored = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(depth32 + x));
          } else {
            alignas(32) uint32_t stored32[8];
            for (int i = 0; i < 8; ++i) stored32[i] = i < n ? depth32[x + i] : 0;
            stored = _mm256_load_si256(reinterpret_cast<const __m256i*>(stored32));
          }
        } else {
          uint16_t tmp[8];
          for (int i = 0; i < 8; ++i) tmp[i] = i < n ? depth16[x + i] : 0;
          stored = _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(tmp)));
        }
        live = _mm256_and_si256(live, depthPassesX8(depthFunc, z, stored));
        if (_mm256_testz_si256(live, live)) continue;
        if (depthWrite) {
          const __m256i merged = _mm256_blendv_epi8(stored, z, live);
          if (depth32 && full) {
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(depth32 + x), merged);
          } else {
            _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), merged);
            if (depth32)
              for (int i = 0; i < n; ++i) depth32[x + i] = lanes[i];
            else
              for (int i = 0; i < n; ++i) depth16[x + i] = static_cast<uint16_t>(lanes[i]);
          }
        }
      }
      if (!anyColor) continue;

      __m256i bytes[4];
      if (isFlat) {
        for (int k = 0; k < 4; ++k) bytes[k] = flatBytes[k];
      } else {
        const __m256 oow = _mm256_div_ps(_mm256_set1_ps(1.0f), planeAt(wPlane, fpx, fpy));
        __m256 c[4];
        for (int k = 0; k < 4; ++k)
          c[k] = flatPrimary ? _mm256_set1_ps(t.flat[k]) : _mm256_mul_ps(planeAt(planes[k], fpx, fpy), oow);
        // GL_LINE_SMOOTH: lineCoverageAt, eight lanes.
        if (lineCoverage) {
          const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
          const __m256 absMask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
          const __m256 x = _mm256_and_ps(_mm256_mul_ps(planeAt(t.coverageX, fpx, fpy), oow), absMask);
          const __m256 z = _mm256_and_ps(_mm256_mul_ps(planeAt(t.coverageZ, fpx, fpy), oow), absMask);
          __m256 across = _mm256_sub_ps(_mm256_set1_ps(t.coverageHalfWidth), x);
          __m256 along = _mm256_sub_ps(_mm256_set1_ps(t.coverageHalfLength), z);
          across = _mm256_min_ps(_mm256_max_ps(across, zero), one);
          along = _mm256_min_ps(_mm256_max_ps(along, zero), one);
          along = _mm256_mul_ps(along, _mm256_set1_ps(t.coverageAlongScale));
          c[3] = _mm256_mul_ps(c[3], _mm256_mul_ps(across, along));
        }
        if (secondary) {
          for (int k = 0; k < 3; ++k)
            c[k] = _mm256_add_ps(c[k], flatSecondary ? _mm256_set1_ps(t.flat[4 + k])
                                                     : _mm256_mul_ps(planeAt(planes[4 + k], fpx, fpy), oow));
        }
        for (int k = 0; k < 4; ++k) bytes[k] = colorToUnormX8(c[k]);
      }

      if (packedStore) {
        __m256i word = _mm256_slli_epi32(bytes[0], 8 * offset[0]);
        word = _mm256_or_si256(word, _mm256_slli_epi32(bytes[1], 8 * offset[1]));
        word = _mm256_or_si256(word, _mm256_slli_epi32(bytes[2], 8 * offset[2]));
        word = _mm256_or_si256(word, _mm256_slli_epi32(bytes[3], 8 * offset[3]));
        __m256i* dst = reinterpret_cast<__m256i*>(colorRow + size_t(x) * 4);
        if (full) {
          _mm256_storeu_si256(dst, _mm256_blendv_epi8(_mm256_loadu_si256(dst), word, live));
        } else {
          alignas(32) uint32_t words[8];
          _mm256_store_si256(reinterpret_cast<__m256i*>(words), word);
          _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), live);
          uint32_t* p = reinterpret_cast<uint32_t*>(colorRow) + x;
          for (int i = 0; i < n; ++i)
            if (lanes[i]) std::memcpy(p + i, &words[i], 4);
        }
      } else {
        alignas(32) uint32_t ch[4][8];
        for (int k = 0; k < 4; ++k) _mm256_store_si256(reinterpret_cast<__m256i*>(ch[k]), bytes[k]);
        _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), live);
        for (int i = 0; i < n; ++i) {
          if (!lanes[i]) continue;
          uint8_t* p = colorRow + size_t(x + i) * bpp;
          for (int k = 0; k < 4; ++k)
            if (colorWrite[k] && offset[k] >= 0) p[offset[k]] = static_cast<uint8_t>(ch[k][i]);
        }
      }
    }
  }
}

}  // namespace glfixed::raster
