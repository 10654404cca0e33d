// Sampling as llvmpipe (Mesa 22.3, gallivm) samples: every rounding below is
// the one gallivm's generated code does, probed by tests/texture/
// sampler_test.cpp against Mesa live (reference/MESA_FACTS.md, "Textures:
// sampling"). llvmpipe runs the fragment shader on 8 lanes (two 2x2 quads);
// with the default GALLIVM_PERF (no brilinear, no rho approximation, quad
// lod) it takes one level of detail per quad.
//
// Two paths, chosen once per draw as lp_build_sample_soa_code chooses them:
// - AoS 8-bit fixed point (lp_bld_sample_aos.c) when every channel fits in
//   an 8-bit unorm, there is no depth comparison, and every wrap mode is
//   GL_REPEAT or GL_CLAMP_TO_EDGE (GL 2.1 cube maps are not seamless, so
//   they take it too);
// - SoA float (lp_bld_sample_soa.c) otherwise.
#pragma GCC optimize("fp-contract=off")

#include "texture/sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace glfixed::texture {
namespace {

using fragment::ColorLanes;
using fragment::kBlockLanes;
using fragment::Lanes;

// x86's float -> int32 conversion (cvttps2dq / cvtps2dq): out of range and
// NaN give INT32_MIN.
inline int32_t toInt(float x) {
  if (!(x >= -2147483648.0f && x < 2147483648.0f)) return INT32_MIN;
  return static_cast<int32_t>(x);
}
inline int32_t itrunc(float x) { return toInt(x); }
inline int32_t ifloor(float x) { return toInt(std::floor(x)); }
// lp_build_iround: round to nearest, ties to even (the MXCSR default).
inline int32_t iround(float x) { return toInt(std::nearbyint(x)); }
inline float fract(float x) { return x - std::floor(x); }
// lp_build_fract_safe: never 1.0 (for tiny negative x).
inline float fractSafe(float x) { return std::min(fract(x), 0.99999994f); }
inline uint32_t floatBits(float x) {
  uint32_t u;
  std::memcpy(&u, &x, 4);
  return u;
}
// lp_build_extract_exponent(x, bias).
inline int32_t extractExponent(float x, int bias) {
  return int32_t((floatBits(x) >> 23) & 255) - (127 - bias);
}
// lp_build_fast_log2: (exponent - 1) + mantissa in [1, 2): exact at powers of two, linear between.
inline float fastLog2(float x) {
  uint32_t m = (floatBits(x) & 0x7fffffu) | 0x3f800000u;
  float mant;
  std::memcpy(&mant, &m, 4);
  return static_cast<float>(extractExponent(x, -1)) + mant;
}

// lp_build_lerp on 8-bit unorm values, widened to 16 bits, with prescaled
// weights (w / 256, w in 0..255): AVX2 pmulhrsw of w and (b - a) << 7, so
// the product rounds half up before the shift: a + ((w * (b - a) + 128) >> 8).
inline int lerp8(int w, int a, int b) { return (a + ((w * (b - a) * 128 + 16384) >> 15)) & 255; }

// lp_build_lerp on floats: lp_build_mad, llvm.fmuladd, fused on this CPU.
inline float lerpF(float w, float a, float b) { return std::fma(w, b - a, a); }

// One coordinate's texel pair and weight for linear filtering.
struct LinearTap {
  int i0, i1;
  int w8;    // AoS weight, 0..255
  float wf;  // SoA weight
};

// ---- AoS (8-bit) coordinate wrapping: lp_build_sample_wrap_*_int ----

inline int aosNearest(float coord, int len, float lenF, bool pot, GLenum wrap) {
  if (wrap == GL_REPEAT) {
    if (pot) return ifloor(coord * lenF) & (len - 1);
    return itrunc(fractSafe(coord) * lenF);
  }
  return std::clamp(ifloor(coord * lenF), 0, len - 1);  // GL_CLAMP_TO_EDGE
}

// v - 128 in 32-bit two's complement, wrapping as llvmpipe's vector integers
// do (a far-off or NaN coordinate of a helper pixel rounds to INT32_MIN).
inline int32_t minus128(int32_t v) { return static_cast<int32_t>(static_cast<uint32_t>(v) - 128u); }

inline LinearTap aosLinear(float coord, int len, bool pot, GLenum wrap) {
  LinearTap tap;
  if (wrap == GL_REPEAT && !pot) {
    // fract of the normalized coordinate, times the size, times 256.
    float f = fract(coord) * static_cast<float>(len);
    int32_t c = minus128(iround(f * 256.0f));
    tap.w8 = c & 255;
    c >>= 8;
    if (c < 0) c = len - 1;
    c = std::min(c, len - 1);
    tap.i0 = c;
    tap.i1 = c == len - 1 ? 0 : c + 1;
    return tap;
  }
  // The coordinate times (size << 8) as a float, rounded to 8 fraction bits.
  int32_t c = minus128(iround(coord * static_cast<float>(len << 8)));
  tap.w8 = c & 255;
  c >>= 8;
  if (wrap == GL_REPEAT) {
    tap.i0 = c & (len - 1);
    tap.i1 = tap.i0 == len - 1 ? 0 : tap.i0 + 1;
  } else {  // GL_CLAMP_TO_EDGE: the second texel is the first at either edge
    bool inside = c >= 0 && c < len - 1;
    tap.i0 = std::clamp(c, 0, len - 1);
    tap.i1 = inside ? tap.i0 + 1 : tap.i0;
  }
  return tap;
}

// ---- SoA (float) coordinate wrapping: lp_build_sample_wrap_* ----

// lp_build_coord_mirror(posOnly): |2 * (x / 2 - round(x / 2))|.
inline float mirror(float x) {
  float h = x * 0.5f;
  float f = h - std::nearbyint(h);
  return std::max(std::fabs(f + f), 0.0f);
}

inline int soaNearest(float coord, int len, float lenF, bool pot, GLenum wrap) {
  switch (wrap) {
    case GL_REPEAT:
      if (pot) return ifloor(coord * lenF) & (len - 1);
      return itrunc(fractSafe(coord) * lenF);
    case GL_CLAMP:
    case GL_CLAMP_TO_EDGE: return std::clamp(itrunc(coord * lenF), 0, len - 1);
    case GL_CLAMP_TO_BORDER: return ifloor(coord * lenF);  // outside: the border colour
    case GL_MIRRORED_REPEAT: return std::min(itrunc(mirror(coord) * lenF), len - 1);
    default: return 0;
  }
}

inline LinearTap soaLinear(float coord, int len, float lenF, bool pot, GLenum wrap) {
  LinearTap tap{};
  float u;
  switch (wrap) {
    case GL_REPEAT:
      if (pot) {
        u = coord * lenF - 0.5f;
        int32_t c = ifloor(u);
        tap.wf = u - std::floor(u);
        tap.i0 = c & (len - 1);
        tap.i1 = (c + 1) & (len - 1);
      } else {
        u = fract(coord) * lenF - 0.5f;
        int32_t c = ifloor(u);
        tap.wf = u - std::floor(u);
        if (u < 0.0f) c = len - 1;
        tap.i0 = c;
        tap.i1 = c != len - 1 ? c + 1 : 0;
      }
      return tap;
    case GL_CLAMP:  // clamp to [0, size] first: the border blends in at the edges
      u = std::min(std::max(coord * lenF, 0.0f), lenF) - 0.5f;
      break;
    case GL_CLAMP_TO_EDGE:
      u = std::max(std::min(coord * lenF, lenF) - 0.5f, 0.0f);
      tap.i0 = ifloor(u);
      tap.wf = u - std::floor(u);
      tap.i1 = std::min(tap.i0 + 1, len - 1);
      return tap;
    case GL_CLAMP_TO_BORDER: u = coord * lenF - 0.5f; break;
    case GL_MIRRORED_REPEAT:
      u = mirror(coord) * lenF - 0.5f;
      tap.i0 = std::max(ifloor(u), 0);
      tap.wf = u - std::floor(u);
      tap.i1 = std::min(ifloor(u) + 1, len - 1);
      return tap;
    default: u = 0; break;
  }
  tap.i0 = ifloor(u);
  tap.wf = u - std::floor(u);
  tap.i1 = tap.i0 + 1;
  return tap;
}

// The level of detail of one quad and what it selects
// (lp_build_lod_selector, lp_build_nearest_mip_level, lp_build_linear_mip_levels).
struct QuadLod {
  bool minified = false;  // lod > 0: the minification filter
  int level0 = 0, level1 = 0;
  float fpart = 0;  // weight of level1
};

// Cube maps give the derivatives on the face explicitly (lp_build_cube_lookup).
struct FaceDerivs {
  float sdx, tdx, sdy, tdy;
};

QuadLod quadLod(const SamplerView& v, const float* s, const float* t, const float* r,
                const FaceDerivs* derivs = nullptr) {
  QuadLod q;
  q.level0 = q.level1 = v.firstLevel;
  if (!v.needLod) return q;
  float lod;
  if (v.minMaxLodEqual) {
    lod = v.minLod;
  } else {
    const SamplerLevel& base = v.levels[v.firstLevel];
    float rho;
    bool squared = v.dims > 1;  // no_rho_approx: the squared length, no sqrt
    if (derivs) {
      float sx = base.sizeF[0] * derivs->sdx, tx = base.sizeF[1] * derivs->tdx;
      float sy = base.sizeF[0] * derivs->sdy, ty = base.sizeF[1] * derivs->tdy;
      float rx = sx * sx + tx * tx, ry = sy * sy + ty * ty;
      rho = rx > ry ? rx : ry;
      if (std::isinf(rho) || std::isnan(rho)) rho = 0;
    } else if (v.dims == 1) {
      // Lanes 0, 1 (right), 2 (below): max(|ds/dx|, |ds/dy|) * width.
      rho = std::max(std::fabs(s[1] - s[0]), std::fabs(s[0] - s[2])) * base.sizeF[0];
    } else {
      float sx = (s[1] - s[0]) * base.sizeF[0], sy = (s[2] - s[0]) * base.sizeF[0];
      float tx = (t[1] - t[0]) * base.sizeF[1], ty = (t[2] - t[0]) * base.sizeF[1];
      float rx = sx * sx + tx * tx, ry = sy * sy + ty * ty;
      if (v.dims == 3) {
        float qx = (r[1] - r[0]) * base.sizeF[2], qy = (r[0] - r[2]) * base.sizeF[2];
        rx = rx + qx * qx;
        ry = ry + qy * qy;
      }
      rho = rx > ry ? rx : ry;
    }
    if (v.lodBias == 0 && !v.applyMinLod && !v.applyMaxLod && v.mipFilter != GL_LINEAR) {
      // No adjustment after the log: the integer level straight from the exponent.
      int ipart =
          squared ? extractExponent(rho, 1) >> 1 : extractExponent(rho * static_cast<float>(M_SQRT2), 0);
      q.minified = rho > 1.0f;
      if (v.mipFilter == GL_NEAREST)
        q.level0 = q.level1 = std::clamp(ipart + v.firstLevel, v.firstLevel, v.lastLevel);
      return q;
    }
    if (!squared) rho = rho * rho;
    lod = fastLog2(rho) * 0.5f;
    if (v.lodBias != 0) lod = lod + v.lodBias;
    if (v.applyMaxLod) lod = std::min(lod, v.maxLod);
    if (v.applyMinLod) lod = std::max(lod, v.minLod);
  }
  q.minified = lod > 0.0f;
  if (v.mipFilter == GL_LINEAR) {
    float fl = std::floor(lod);
    int l0 = toInt(fl) + v.firstLevel;
    q.fpart = lod - fl;
    if (l0 < v.firstLevel) {
      q.level0 = q.level1 = v.firstLevel;
      q.fpart = 0;
    } else if (l0 >= v.lastLevel) {
      q.level0 = q.level1 = v.lastLevel;
      q.fpart = 0;
    } else {
      q.level0 = l0;
      q.level1 = l0 + 1;
    }
  } else if (v.mipFilter == GL_NEAREST) {
    q.level0 = q.level1 = std::clamp(iround(lod) + v.firstLevel, v.firstLevel, v.lastLevel);
  }
  return q;
}

// ---- AoS sampling of one lane at one level: 8-bit RGBA ----

void fetch8(const SamplerView& v, const TextureImage& img, int x, int y, int z, int out[4]) {
  // The common formats read directly (the same values decodeTexelUnorm8 gives).
  if (v.format == TexelFormat::RGBA8 || v.format == TexelFormat::RGBX8) {
    const uint8_t* p = img.texels.data() + size_t(z) * img.imageStride + size_t(y) * img.rowStride + size_t(x) * 4;
    out[0] = p[0], out[1] = p[1], out[2] = p[2];
    out[3] = v.format == TexelFormat::RGBA8 ? p[3] : 255;
    return;
  }
  uint8_t c[4];
  decodeTexelUnorm8(v.format, img.texel(x, y, z), c);
  for (int k = 0; k < 4; ++k) out[k] = c[k];
}

void sampleAos(const SamplerView& v, const SamplerLevel& lv, int face, GLenum filter, float s, float t,
               float r, int out[4]) {
  const TextureImage& img = *lv.face[face];
  if (filter == GL_NEAREST) {
    int x = aosNearest(s, lv.size[0], lv.sizeF[0], lv.pot[0], v.wrap[0]);
    int y = v.dims >= 2 ? aosNearest(t, lv.size[1], lv.sizeF[1], lv.pot[1], v.wrap[1]) : 0;
    int z = v.dims >= 3 ? aosNearest(r, lv.size[2], lv.sizeF[2], lv.pot[2], v.wrap[2]) : 0;
    fetch8(v, img, x, y, z, out);
    return;
  }
  LinearTap a = aosLinear(s, lv.size[0], lv.pot[0], v.wrap[0]);
  LinearTap b = v.dims >= 2 ? aosLinear(t, lv.size[1], lv.pot[1], v.wrap[1]) : LinearTap{0, 0, 0, 0};
  LinearTap c = v.dims >= 3 ? aosLinear(r, lv.size[2], lv.pot[2], v.wrap[2]) : LinearTap{0, 0, 0, 0};
  int planes = v.dims >= 3 ? 2 : 1;
  int plane[2][4];
  for (int p = 0; p < planes; ++p) {
    int z = p ? c.i1 : c.i0;
    int t00[4], t01[4], t10[4], t11[4];
    fetch8(v, img, a.i0, b.i0, z, t00);
    fetch8(v, img, a.i1, b.i0, z, t01);
    if (v.dims >= 2) {
      fetch8(v, img, a.i0, b.i1, z, t10);
      fetch8(v, img, a.i1, b.i1, z, t11);
    }
    for (int k = 0; k < 4; ++k) {
      int row0 = lerp8(a.w8, t00[k], t01[k]);
      plane[p][k] = v.dims >= 2 ? lerp8(b.w8, row0, lerp8(a.w8, t10[k], t11[k])) : row0;
    }
  }
  for (int k = 0; k < 4; ++k) out[k] = planes == 2 ? lerp8(c.w8, plane[0][k], plane[1][k]) : plane[0][k];
}

// ---- SoA sampling of one lane at one level: float RGBA ----

void fetchF(const SamplerView& v, const SamplerLevel& lv, const TextureImage& img, int x, int y, int z,
            float out[4]) {
  bool outside = (v.border[0] && (x < 0 || x >= lv.size[0])) ||
                 (v.dims >= 2 && v.border[1] && (y < 0 || y >= lv.size[1])) ||
                 (v.dims >= 3 && v.border[2] && (z < 0 || z >= lv.size[2]));
  if (outside) {
    for (int k = 0; k < 4; ++k) out[k] = v.borderColor[k];
    return;
  }
  decodeTexelFloat(v.format, img.texel(x, y, z), out);
}

// lp_build_sample_comparefunc: ref FUNC texel, ordered (false with a NaN)
// except GL_NOTEQUAL, unordered (true with a NaN).
bool compareDepth(GLenum func, float ref, float texel) {
  switch (func) {
    case GL_LEQUAL: return ref <= texel;
    case GL_GEQUAL: return ref >= texel;
    case GL_LESS: return ref < texel;
    case GL_GREATER: return ref > texel;
    case GL_EQUAL: return ref == texel;
    case GL_NOTEQUAL: return !(ref == texel);
    case GL_ALWAYS: return true;
    default: return false;  // GL_NEVER
  }
}

// A texel for filtering: with GL_COMPARE_R_TO_TEXTURE, channel 0 is the
// comparison's 0 or 1 (linear filtering lerps the four results).
void fetchTexel(const SamplerView& v, const SamplerLevel& lv, const TextureImage& img, int x, int y, int z,
                float ref, float out[4]) {
  fetchF(v, lv, img, x, y, z, out);
  if (v.compare) out[0] = compareDepth(v.compareFunc, ref, out[0]) ? 1.0f : 0.0f;
}

// `snap`: a lane that wants the nearest filter inside llvmpipe's combined
// min/mag path: its linear weights become 1 where above 0.5, else 0.
void sampleSoa(const SamplerView& v, const SamplerLevel& lv, int face, GLenum filter, bool snap, float s,
               float t, float r, float ref, float out[4]) {
  const TextureImage& img = *lv.face[face];
  if (filter == GL_NEAREST) {
    int x = soaNearest(s, lv.size[0], lv.sizeF[0], lv.pot[0], v.wrap[0]);
    int y = v.dims >= 2 ? soaNearest(t, lv.size[1], lv.sizeF[1], lv.pot[1], v.wrap[1]) : 0;
    int z = v.dims >= 3 ? soaNearest(r, lv.size[2], lv.sizeF[2], lv.pot[2], v.wrap[2]) : 0;
    fetchTexel(v, lv, img, x, y, z, ref, out);
    return;
  }
  LinearTap a = soaLinear(s, lv.size[0], lv.sizeF[0], lv.pot[0], v.wrap[0]);
  LinearTap b =
      v.dims >= 2 ? soaLinear(t, lv.size[1], lv.sizeF[1], lv.pot[1], v.wrap[1]) : LinearTap{0, 0, 0, 0};
  LinearTap c =
      v.dims >= 3 ? soaLinear(r, lv.size[2], lv.sizeF[2], lv.pot[2], v.wrap[2]) : LinearTap{0, 0, 0, 0};
  if (snap) {
    a.wf = a.wf > 0.5f ? 1.0f : 0.0f;
    b.wf = b.wf > 0.5f ? 1.0f : 0.0f;
    c.wf = c.wf > 0.5f ? 1.0f : 0.0f;
  }
  int planes = v.dims >= 3 ? 2 : 1;
  float plane[2][4];
  for (int p = 0; p < planes; ++p) {
    int z = p ? c.i1 : c.i0;
    float t00[4], t01[4], t10[4], t11[4];
    fetchTexel(v, lv, img, a.i0, b.i0, z, ref, t00);
    fetchTexel(v, lv, img, a.i1, b.i0, z, ref, t01);
    if (v.dims >= 2) {
      fetchTexel(v, lv, img, a.i0, b.i1, z, ref, t10);
      fetchTexel(v, lv, img, a.i1, b.i1, z, ref, t11);
    }
    for (int k = 0; k < 4; ++k) {
      float row0 = lerpF(a.wf, t00[k], t01[k]);
      plane[p][k] = v.dims >= 2 ? lerpF(b.wf, row0, lerpF(a.wf, t10[k], t11[k])) : row0;
    }
  }
  for (int k = 0; k < 4; ++k) out[k] = planes == 2 ? lerpF(c.wf, plane[0][k], plane[1][k]) : plane[0][k];
}

// lp_build_cube_lookup: the face of the major axis (ties: r, then t over s),
// the other two coordinates mirrored by its sign, times 0.5 / |major|, plus 0.5.
struct CubeCoord {
  int face;
  float sc, tc;  // on the face before the projection
  float ma;      // the major axis coordinate, signed
  int axis;      // 0 x, 1 y, 2 z
};

inline CubeCoord cubeFace(float s, float t, float r) {
  float as = std::fabs(s), at = std::fabs(t), ar = std::fabs(r);
  bool sOverT = as > at, rMajor = ar >= (as > at ? as : at);
  CubeCoord c;
  c.axis = rMajor ? 2 : sOverT ? 0 : 1;
  c.ma = c.axis == 0 ? s : c.axis == 1 ? t : r;
  bool neg = std::signbit(c.ma);
  auto flip = [](float x, bool f) { return f ? -x : x; };
  if (c.axis == 0)
    c.sc = flip(-r, neg), c.tc = -t;
  else if (c.axis == 1)
    c.sc = s, c.tc = flip(r, neg);
  else
    c.sc = flip(s, neg), c.tc = -t;
  c.face = 2 * c.axis + (neg ? 1 : 0);
  return c;
}

// A lane's coordinate after the projective division.
inline float cs(const Lanes& c, const Lanes& q, int lane) { return c[lane] * (1.0f / q[lane]); }

GLenum imageFilter(GLenum filter) {
  return filter == GL_LINEAR || filter == GL_LINEAR_MIPMAP_NEAREST || filter == GL_LINEAR_MIPMAP_LINEAR
             ? GL_LINEAR
             : GL_NEAREST;
}
GLenum mipFilterOf(GLenum filter) {
  switch (filter) {
    case GL_NEAREST_MIPMAP_NEAREST:
    case GL_LINEAR_MIPMAP_NEAREST: return GL_NEAREST;
    case GL_NEAREST_MIPMAP_LINEAR:
    case GL_LINEAR_MIPMAP_LINEAR: return GL_LINEAR;
    default: return GL_NONE;
  }
}
bool isPot(int n) { return (n & (n - 1)) == 0; }

}  // namespace

bool makeSamplerView(const TextureObject& texture, GLenum target, float unitLodBias, SamplerView& out) {
  out = SamplerView{};
  out.texture = &texture;
  out.target = target;
  out.unitLodBias = unitLodBias;
  const SamplerParams& p = texture.params;
  out.cube = target == GL_TEXTURE_CUBE_MAP;
  out.dims = target == GL_TEXTURE_1D ? 1 : target == GL_TEXTURE_3D ? 3 : 2;
  int faces = out.cube ? kMaxCubeFaces : 1;
  int base = p.baseLevel;
  if (base < 0 || base >= kMaxTextureLevels) return false;
  const TextureImage& b = texture.level(0, base);
  if (!b.defined()) return false;
  out.minImage = imageFilter(p.minFilter);
  out.magImage = imageFilter(p.magFilter);
  out.mipFilter = mipFilterOf(p.minFilter);
  out.format = b.format;

  // Completeness (GL 2.1 §3.8.10): the base level, and with a mipmap filter
  // every level down to 1x1 or the maximum level, each half the one before,
  // in the base level's format; a cube map's faces square and alike.
  int last = base;
  // Measured: a maximum level below the base level leaves a non-mipmapped
  // texture complete (Mesa's base-level completeness), but llvmpipe then
  // samples (0, 0, 0, 0) (Mesa skips the rest of its checks, and the view it
  // builds has no level to read); mipmapped, the texture is incomplete.
  if (p.maxLevel < base) {
    if (out.mipFilter != GL_NONE) return false;
    out.samplesZero = true;
  }
  if (out.mipFilter != GL_NONE) {
    int maxSize = std::max({b.width, out.dims >= 2 ? b.height : 1, out.dims >= 3 ? b.depth : 1});
    int log2 = 0;
    while ((maxSize >> log2) > 1) ++log2;
    last = std::min({base + log2, p.maxLevel, kMaxTextureLevels - 1});
  }
  for (int level = base; level <= last; ++level) {
    int shift = level - base;
    int w = std::max(b.width >> shift, 1), h = out.dims >= 2 ? std::max(b.height >> shift, 1) : 1;
    int d = out.dims >= 3 ? std::max(b.depth >> shift, 1) : 1;
    SamplerLevel& lv = out.levels[level];
    for (int f = 0; f < faces; ++f) {
      const TextureImage& img = texture.level(f, level);
      if (!img.defined() || img.width != w || (out.dims >= 2 && img.height != h) ||
          (out.dims >= 3 && img.depth != d) || img.format != b.format ||
          img.internalFormat != b.internalFormat)
        return false;
      if (out.cube && img.width != img.height) return false;
      lv.face[f] = &img;
    }
    lv.size[0] = w, lv.size[1] = h, lv.size[2] = d;
    for (int k = 0; k < 3; ++k) {
      lv.sizeF[k] = static_cast<float>(lv.size[k]);
      lv.pot[k] = isPot(lv.size[k]);
    }
  }
  out.firstLevel = base;
  out.lastLevel = last;

  out.wrap[0] = p.wrapS, out.wrap[1] = p.wrapT, out.wrap[2] = p.wrapR;
  // llvmpipe ignores a cube map's wrap modes: s and t clamp to the edge.
  if (out.cube) out.wrap[0] = out.wrap[1] = GL_CLAMP_TO_EDGE;
  bool anyLinear = out.minImage == GL_LINEAR || out.magImage == GL_LINEAR;
  for (int k = 0; k < 3; ++k)
    out.border[k] = out.wrap[k] == GL_CLAMP_TO_BORDER || (out.wrap[k] == GL_CLAMP && anyLinear);
  // The border colour as st_translate_color maps it to the base format, and
  // clamped to [0, 1] for a unorm format (lp_build_clamp_border_color).
  const TexelFormatInfo& info = texelFormatInfo(out.format);
  float bc[4] = {p.borderColor.r, p.borderColor.g, p.borderColor.b, p.borderColor.a};
  switch (info.baseFormat) {
    case GL_RGB: bc[3] = 1; break;
    case GL_ALPHA: bc[0] = bc[1] = bc[2] = 0; break;
    case GL_LUMINANCE: bc[1] = bc[2] = bc[0], bc[3] = 1; break;
    case GL_LUMINANCE_ALPHA: bc[1] = bc[2] = bc[0]; break;
    case GL_INTENSITY: bc[1] = bc[2] = bc[3] = bc[0]; break;
    default: break;
  }
  for (int k = 0; k < 4; ++k)
    out.borderColor[k] = info.fitsUnorm8 ? std::min(std::max(bc[k], 0.0f), 1.0f) : bc[k];

  // The gallium sampler state Mesa derives (samplerobj.c, st_convert_sampler):
  // min lod at least 0, the unit's bias added to the object's.
  // Both biases are quantized to 1/256 before they are added
  // (util_quantize_lod_bias: clamp to [-16, 16], roundf(bias * 256) / 256).
  auto quantize = [](float bias) {
    return std::roundf(std::min(std::max(bias, -16.0f), 16.0f) * 256.0f) / 256.0f;
  };
  out.lodBias = quantize(p.lodBias) + quantize(unitLodBias);
  out.minLod = std::max(p.minLod, 0.0f);
  out.maxLod = p.maxLod;
  out.needLod = out.mipFilter != GL_NONE || out.minImage != out.magImage;
  if (out.needLod) {
    out.minMaxLodEqual = out.minLod == out.maxLod;
    out.applyMinLod = !out.minMaxLodEqual && out.minLod > 0.0f;
    out.applyMaxLod = !out.minMaxLodEqual && out.maxLod < 14.0f;  // PIPE_MAX_TEXTURE_LEVELS - 1
  }

  out.depth = info.baseFormat == GL_DEPTH_COMPONENT;
  out.depthTextureMode = p.depthTextureMode;
  out.compare = out.depth && p.compareMode == GL_COMPARE_R_TO_TEXTURE;
  out.compareFunc = p.compareFunc;

  auto simple = [](GLenum w) { return w == GL_REPEAT || w == GL_CLAMP_TO_EDGE; };
  // A per-pixel lod (cube maps with a mip filter) keeps the AoS path only
  // with equal min and mag filters.
  bool perPixelLod = out.cube && out.mipFilter != GL_NONE;
  out.unorm8 = info.fitsUnorm8 && p.compareMode == GL_NONE && simple(out.wrap[0]) &&
               !(perPixelLod && out.minImage != out.magImage) && (out.dims < 2 || simple(out.wrap[1])) &&
               (out.dims < 3 || simple(out.wrap[2]));
  return true;
}

void sampleBlock(const SamplerView& v, const Lanes& s, const Lanes& t, const Lanes& r, const Lanes& q,
                 ColorLanes& out) {
  if (v.samplesZero) {
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < kBlockLanes; ++i) out.c[k][i] = 0.0f;
    return;
  }
  // The projective division of the fixed-function shader's TXP: one
  // reciprocal (a division), then products.
  float ps[kBlockLanes], pt[kBlockLanes], pr[kBlockLanes], ref[kBlockLanes];
  for (int i = 0; i < kBlockLanes; ++i) {
    float rcp = 1.0f / q[i];
    ps[i] = s[i] * rcp;
    pt[i] = t[i] * rcp;
    pr[i] = r[i] * rcp;
    // The reference value, r after the division, clamped to [0, 1] for the
    // (unorm) depth formats (lp_build_sample_soa_code): max, then min.
    ref[i] = std::min(std::max(pr[i], 0.0f), 1.0f);
  }
  // The level of detail of each lane: per quad, except cube maps with a mip
  // filter, where llvmpipe takes it per pixel.
  QuadLod lod[kBlockLanes];
  int faces[kBlockLanes] = {};
  if (v.cube) {
    CubeCoord cc[kBlockLanes];
    for (int i = 0; i < kBlockLanes; ++i) {
      cc[i] = cubeFace(ps[i], pt[i], pr[i]);
      float ima = std::fabs(cc[i].ma) > 0.0f ? 0.5f / std::fabs(cc[i].ma) : 0.0f;
      faces[i] = cc[i].face;
      ps[i] = cc[i].sc * ima + 0.5f;
      pt[i] = cc[i].tc * ima + 0.5f;
    }
    bool perLane = v.mipFilter != GL_NONE;
    for (int i = 0; i < kBlockLanes; ++i) {
      if (!v.needLod || v.minMaxLodEqual) {
        lod[i] = quadLod(v, nullptr, nullptr, nullptr);
        continue;
      }
      if (!perLane && (i & 3)) {  // per quad: the top-left lane's
        lod[i] = lod[i & ~3];
        continue;
      }
      // lp_build_ddx / ddy: the difference along the lane's row / column of
      // its quad, carried onto the lane's face: (dsc - dma * (1 / ma) * sc) * (0.5 / ma).
      int base = i & ~3, k = i & 3;
      int x0 = base + (k & 2), x1 = x0 + 1, y0 = base + (k & 1), y1 = y0 + 2;
      float ddx[3] = {cs(s, q, x1) - cs(s, q, x0), cs(t, q, x1) - cs(t, q, x0), cs(r, q, x1) - cs(r, q, x0)};
      float ddy[3] = {cs(s, q, y1) - cs(s, q, y0), cs(t, q, y1) - cs(t, q, y0), cs(r, q, y1) - cs(r, q, y0)};
      const CubeCoord& c = cc[i];
      float ima = 1.0f / c.ma, imahalf = 0.5f * ima;
      bool neg = std::signbit(c.ma);
      auto flip = [](float x, bool f) { return f ? -x : x; };
      auto onFace = [&](const float* d, float& sd, float& td) {
        if (c.axis == 0)
          sd = flip(-d[2], neg), td = -d[1];
        else if (c.axis == 1)
          sd = d[0], td = flip(d[2], neg);
        else
          sd = flip(d[0], neg), td = -d[1];
      };
      float sdx, tdx, sdy, tdy;
      onFace(ddx, sdx, tdx);
      onFace(ddy, sdy, tdy);
      float madx = ddx[c.axis] * ima, mady = ddy[c.axis] * ima;
      FaceDerivs fd;
      fd.sdx = (sdx - madx * c.sc) * imahalf;
      fd.tdx = (tdx - madx * c.tc) * imahalf;
      fd.sdy = (sdy - mady * c.sc) * imahalf;
      fd.tdy = (tdy - mady * c.tc) * imahalf;
      lod[i] = quadLod(v, nullptr, nullptr, nullptr, &fd);
    }
  } else {
    QuadLod q0 = quadLod(v, ps, pt, pr), q1 = quadLod(v, ps + 4, pt + 4, pr + 4);
    for (int i = 0; i < kBlockLanes; ++i) lod[i] = i < 4 ? q0 : q1;
  }
  bool anyFraction = false;
  for (int i = 0; i < kBlockLanes; ++i) anyFraction |= lod[i].fpart > 0;

  if (v.unorm8) {
    // AoS: with different min and mag filters llvmpipe samples each quad
    // on its own (4 lanes), so each quad takes its own filter (and the mip
    // lerp runs when any lane of the block has a fraction).
    for (int i = 0; i < kBlockLanes; ++i) {
      const QuadLod& ql = lod[i];
      bool useMin = v.minImage == v.magImage || ql.minified;
      GLenum filter = useMin ? v.minImage : v.magImage;
      int c0[4];
      sampleAos(v, v.levels[ql.level0], faces[i], filter, ps[i], pt[i], pr[i], c0);
      if (useMin && v.mipFilter == GL_LINEAR && anyFraction) {
        int c1[4];
        sampleAos(v, v.levels[ql.level1], faces[i], filter, ps[i], pt[i], pr[i], c1);
        int w = toInt(ql.fpart * 256.0f);
        for (int k = 0; k < 4; ++k) c0[k] = lerp8(w, c0[k], c1[k]);
      }
      for (int k = 0; k < 4; ++k) out.c[k][i] = unormToFloat(static_cast<uint32_t>(c0[k]), 8);
    }
    return;
  }

  // SoA: the block at once. With different min and mag filters, if any
  // lane wants linear, every lane samples linearly with the min mip filter
  // and the nearest lanes snap their weights (lp_build_sample_mipmap_both).
  bool combined = false, allNearestMip = v.mipFilter != GL_NONE;
  if (v.minImage != v.magImage) {
    for (int i = 0; i < kBlockLanes; ++i)
      combined |= v.minImage == GL_LINEAR ? lod[i].minified : !lod[i].minified;
    if (!combined && v.minImage == GL_LINEAR) allNearestMip = false;  // every lane magnified
  }
  for (int i = 0; i < kBlockLanes; ++i) {
    const QuadLod& ql = lod[i];
    GLenum filter;
    bool snap = false, mip = v.mipFilter != GL_NONE;
    if (v.minImage == v.magImage) {
      filter = v.minImage;
    } else if (combined) {
      filter = GL_LINEAR;
      snap = (ql.minified ? v.minImage : v.magImage) == GL_NEAREST;
    } else {
      filter = GL_NEAREST;
      mip = allNearestMip;
    }
    float c0[4];
    sampleSoa(v, v.levels[ql.level0], faces[i], filter, snap, ps[i], pt[i], pr[i], ref[i], c0);
    if (mip && v.mipFilter == GL_LINEAR && anyFraction) {
      float c1[4];
      sampleSoa(v, v.levels[ql.level1], faces[i], filter, snap, ps[i], pt[i], pr[i], ref[i], c1);
      for (int k = 0; k < 4; ++k) c0[k] = lerpF(ql.fpart, c0[k], c1[k]);
    }
    if (v.depth) {
      // The depth (or the comparison's result) in channel 0, through the
      // sampler view's swizzle for GL_DEPTH_TEXTURE_MODE (st_sampler_view).
      float d = c0[0];
      switch (v.depthTextureMode) {
        case GL_INTENSITY: c0[0] = c0[1] = c0[2] = c0[3] = d; break;
        case GL_ALPHA: c0[0] = c0[1] = c0[2] = 0.0f, c0[3] = d; break;
        default: c0[0] = c0[1] = c0[2] = d, c0[3] = 1.0f; break;  // GL_LUMINANCE
      }
    }
    for (int k = 0; k < 4; ++k) out.c[k][i] = c0[k];
  }
}

}  // namespace glfixed::texture
