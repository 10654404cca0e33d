// texture::sampleBlock against llvmpipe, live: each case is drawn by
// sampler_probe.c on the system's OSMesa (a window-filling quad, GL_REPLACE)
// and every pixel is compared with sampleBlock's colour for the same
// texture coordinates, converted as the fragment stage converts it
// (raster::colorToUnorm8). The coordinates are affine in window space with
// dyadic steps, so that llvmpipe's interpolation of them is exact and the
// test feeds sampleBlock the very values llvmpipe sampled with.
#include "texture/sampler.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "raster/raster.h"

#ifndef GLFX_SAMPLER_PROBE
#define GLFX_SAMPLER_PROBE ""
#endif

namespace glfixed::texture {
namespace {

struct Affine {  // value = c + dx * X + dy * Y, window coordinates (y up)
  float c = 0, dx = 0, dy = 0;
  float at(float x, float y) const { return c + dx * x + dy * y; }
};

struct Case {
  int width = 64, height = 64;  // window
  GLenum target = GL_TEXTURE_2D;
  GLenum format = GL_RGBA;                 // upload format (internal format the same), GL_UNSIGNED_BYTE
  // A depth texture: uploaded as GL_DEPTH_COMPONENT, GL_UNSIGNED_INT.
  GLenum depthInternalFormat = 0;          // GL_DEPTH_COMPONENT16, 24 or 32
  std::vector<std::array<int, 3>> levels;  // sizes of levels 0..n-1
  SamplerParams params;
  float unitLodBias = 0;
  Affine s, t, r, q{1, 0, 0};
  unsigned seed = 1;
};

TexelFormat texelFormatOf(GLenum format) {
  switch (format) {
    case GL_DEPTH_COMPONENT16: return TexelFormat::Z16;
    case GL_DEPTH_COMPONENT24: return TexelFormat::Z24;
    case GL_DEPTH_COMPONENT32: return TexelFormat::Z32;
    case GL_RGB: return TexelFormat::RGBX8;
    case GL_LUMINANCE: return TexelFormat::L8;
    case GL_ALPHA: return TexelFormat::A8;
    case GL_INTENSITY: return TexelFormat::I8;
    case GL_LUMINANCE_ALPHA: return TexelFormat::L8A8;
    default: return TexelFormat::RGBA8;
  }
}
int componentsOf(GLenum format) {
  switch (format) {
    case GL_RGB: return 3;
    case GL_LUMINANCE:
    case GL_ALPHA:
    case GL_INTENSITY: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 4;
  }
}

void put(std::string& buf, uint32_t w) { buf.append(reinterpret_cast<const char*>(&w), 4); }
void putf(std::string& buf, float f) {
  uint32_t w;
  std::memcpy(&w, &f, 4);
  put(buf, w);
}

// Runs the probe; empty when it cannot run.
std::vector<uint8_t> drawOnMesa(const Case& c, const std::vector<std::vector<uint8_t>>& data) {
  std::string in;
  put(in, c.width), put(in, c.height), put(in, c.target);
  int faces = c.target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
  put(in, uint32_t(c.levels.size() * faces));
  GLint internal = c.depthInternalFormat      ? GLint(c.depthInternalFormat)
                   : c.format == GL_INTENSITY ? GL_INTENSITY8
                                              : GLint(c.format);
  GLenum upload = c.depthInternalFormat      ? GL_DEPTH_COMPONENT
                  : c.format == GL_INTENSITY ? GL_LUMINANCE
                                             : c.format;
  GLenum type = c.depthInternalFormat ? GL_UNSIGNED_INT : GL_UNSIGNED_BYTE;
  for (int f = 0; f < faces; ++f)
    for (size_t l = 0; l < c.levels.size(); ++l) {
      const std::vector<uint8_t>& bytes = data[f * c.levels.size() + l];
      put(in, faces == 6 ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + f : c.target);
      put(in, uint32_t(l)), put(in, uint32_t(internal));
      put(in, c.levels[l][0]), put(in, c.levels[l][1]), put(in, c.levels[l][2]);
      put(in, upload), put(in, type), put(in, uint32_t(bytes.size()));
      in.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      in.append((4 - bytes.size() % 4) % 4, '\0');
    }
  const SamplerParams& p = c.params;
  put(in, p.minFilter), put(in, p.magFilter), put(in, p.wrapS), put(in, p.wrapT), put(in, p.wrapR);
  for (int k = 0; k < 4; ++k) putf(in, p.borderColor[k]);
  putf(in, p.lodBias), putf(in, p.minLod), putf(in, p.maxLod);
  put(in, uint32_t(p.baseLevel)), put(in, uint32_t(p.maxLevel));
  putf(in, c.unitLodBias);
  put(in, p.compareMode), put(in, p.compareFunc), put(in, p.depthTextureMode);
  const float X[4] = {0, float(c.width), float(c.width), 0}, Y[4] = {0, 0, float(c.height), float(c.height)};
  const int order[6] = {0, 1, 2, 0, 2, 3};
  put(in, 6);
  for (int i : order) {
    putf(in, X[i]), putf(in, Y[i]);
    putf(in, c.s.at(X[i], Y[i])), putf(in, c.t.at(X[i], Y[i])), putf(in, c.r.at(X[i], Y[i]));
    putf(in, c.q.at(X[i], Y[i]));
  }
  char inName[] = "/tmp/glfx_sampler_XXXXXX";
  int fd = mkstemp(inName);
  if (fd < 0) return {};
  FILE* f = fdopen(fd, "wb");
  fwrite(in.data(), 1, in.size(), f);
  fclose(f);
  std::string cmd = std::string(GLFX_SAMPLER_PROBE) + " < " + inName;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::vector<uint8_t> pixels(size_t(c.width) * c.height * 4);
  size_t got = pipe ? fread(pixels.data(), 1, pixels.size(), pipe) : 0;
  int status = pipe ? pclose(pipe) : -1;
  remove(inName);
  if (got != pixels.size() || status != 0) return {};
  return pixels;
}

// Draws `c` on Mesa and samples it with sampleBlock; returns the pixels
// compared, and fails on every channel that differs.
int compareWithMesa(const Case& c) {
  if (std::string(GLFX_SAMPLER_PROBE).empty()) return 0;
  std::mt19937 rng(c.seed);
  int faces = c.target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
  std::vector<std::vector<uint8_t>> data;
  TextureObject tex;
  tex.target = c.target;
  tex.params = c.params;
  for (int f = 0; f < faces; ++f)
    for (size_t l = 0; l < c.levels.size(); ++l) {
      int w = c.levels[l][0], h = c.levels[l][1], d = c.levels[l][2];
      int comps = c.depthInternalFormat ? 4 : componentsOf(c.format);
      std::vector<uint8_t> bytes(size_t(w) * h * d * comps);
      for (uint8_t& b : bytes) b = uint8_t(rng());
      TextureImage& img = tex.face[f][l];
      img.width = w, img.height = h, img.depth = d;
      img.internalFormat = c.depthInternalFormat ? c.depthInternalFormat : c.format;
      img.format = texelFormatOf(img.internalFormat);
      int bpt = texelFormatInfo(img.format).bytesPerTexel;
      img.rowStride = size_t(w) * bpt, img.imageStride = img.rowStride * h;
      img.texels.assign(img.imageStride * d, 0);
      if (c.depthInternalFormat) {
        // Random depths whose low bits repeat the high ones, so that any
        // conversion of the 32-bit upload to 16 or 24 bits stores x.
        for (int i = 0; i < w * h * d; ++i) {
          uint32_t v;
          std::memcpy(&v, &bytes[size_t(i) * 4], 4);
          uint32_t x = img.format == TexelFormat::Z16 ? v >> 16 : img.format == TexelFormat::Z24 ? v >> 8 : v;
          // Some depths exactly 0 and 1: only they tell whether the reference is clamped.
          uint32_t one = img.format == TexelFormat::Z16   ? 0xffffu
                         : img.format == TexelFormat::Z24 ? 0xffffffu
                                                          : ~0u;
          if (i % 4 == 1) x = 0;
          if (i % 4 == 2) x = one;
          if (img.format == TexelFormat::Z16) v = x << 16 | x;
          if (img.format == TexelFormat::Z24) v = x << 8 | x >> 16;
          if (img.format == TexelFormat::Z32) v = x;
          std::memcpy(&bytes[size_t(i) * 4], &v, 4);
          std::memcpy(&img.texels[size_t(i) * bpt], &x, size_t(bpt));
        }
      } else {
        for (int i = 0; i < w * h * d; ++i)
          for (int k = 0; k < bpt; ++k)
            img.texels[size_t(i) * bpt + k] = k < comps ? bytes[size_t(i) * comps + k] : 0;
      }
      data.push_back(std::move(bytes));
    }
  std::vector<uint8_t> mesa = drawOnMesa(c, data);
  if (mesa.empty()) {
    ADD_FAILURE() << "the probe did not run";
    return 0;
  }
  SamplerView view;
  bool complete = makeSamplerView(tex, c.target, c.unitLodBias, view);
  int compared = 0, reported = 0;
  for (int by = 0; by < c.height; by += 2)
    for (int bx = 0; bx < c.width; bx += 4) {
      fragment::Lanes s, t, r, q;
      for (int i = 0; i < fragment::kBlockLanes; ++i) {
        // Lane i in llvmpipe's y-down window space; GL's row is flipped.
        float x = float(bx + fragment::laneX(i)) + 0.5f;
        float y = float(c.height - 1 - (by + fragment::laneY(i))) + 0.5f;
        s[i] = c.s.at(x, y), t[i] = c.t.at(x, y), r[i] = c.r.at(x, y), q[i] = c.q.at(x, y);
      }
      fragment::ColorLanes out{};
      if (complete) sampleBlock(view, s, t, r, q, out);
      for (int i = 0; i < fragment::kBlockLanes; ++i) {
        int px = bx + fragment::laneX(i), row = c.height - 1 - (by + fragment::laneY(i));
        const uint8_t* m = &mesa[(size_t(row) * c.width + px) * 4];
        for (int k = 0; k < 4; ++k) {
          // An incomplete texture disables the unit: the fragment keeps its colour (white).
          // GL_REPLACE keeps the fragment's colour of an alpha texture (table 3.22).
          GLenum base = c.depthInternalFormat ? c.params.depthTextureMode : c.format;
          bool fragmentColour = !complete || (base == GL_ALPHA && k < 3);
          uint8_t ours = fragmentColour ? 255 : raster::colorToUnorm8(out.c[k][i]);
          if (ours != m[k] && reported++ < 8)
            ADD_FAILURE() << "pixel (" << px << ", " << row << ") channel " << k << ": mesa " << int(m[k])
                          << ", ours " << int(ours) << " (s " << s[i] << ", t " << t[i] << ", q " << q[i]
                          << ")";
        }
        ++compared;
      }
    }
  EXPECT_EQ(reported, 0) << "channels that differ from llvmpipe";
  return compared;
}

Case rgba2d(int w, int h, GLenum minF, GLenum magF, GLenum wrap) {
  Case c;
  c.levels = {{w, h, 1}};
  c.params.minFilter = minF, c.params.magFilter = magF;
  c.params.wrapS = c.params.wrapT = wrap;
  c.params.borderColor = {0.25f, 0.5f, 0.75f, 1.0f};
  return c;
}

// Magnification: 16 pixels per texel step pattern skewed so that the
// weights cover every 1/256 and the coordinates run past [0, 1].
TEST(SamplerMesa, Rgba8MagnifiedNearestAndLinearEveryWrap) {
  const GLenum wraps[] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};
  int pixels = 0;
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (GLenum wrap : wraps)
      for (int size : {8, 5}) {
        Case c = rgba2d(size, size == 8 ? 4 : 3, filter, filter, wrap);
        c.s = {-0.375f, 1.0f / 32, 1.0f / 1024};
        c.t = {-0.25f, -1.0f / 2048, 1.0f / 40.0f * 0 + 1.0f / 32};
        SCOPED_TRACE(testing::Message() << "filter " << filter << " wrap " << wrap << " size " << size);
        pixels += compareWithMesa(c);
      }
  RecordProperty("pixels", pixels);
}

TEST(SamplerMesa, Rgba8MinifiedNearestAndLinearEveryWrap) {
  const GLenum wraps[] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};
  int pixels = 0;
  for (GLenum filter : {GL_NEAREST, GL_LINEAR})
    for (GLenum wrap : wraps)
      for (int size : {64, 37}) {
        Case c = rgba2d(size, size, filter, filter, wrap);
        c.s = {-0.5f, 3.0f / 64, 1.0f / 256};
        c.t = {-0.25f, -1.0f / 512, 5.0f / 128};
        SCOPED_TRACE(testing::Message() << "filter " << filter << " wrap " << wrap << " size " << size);
        pixels += compareWithMesa(c);
      }
  RecordProperty("pixels", pixels);
}

Case mipmapped2d(GLenum format, int size, GLenum minF, GLenum magF, GLenum wrap) {
  Case c;
  c.format = format;
  for (int w = size, h = size;; w = std::max(w / 2, 1), h = std::max(h / 2, 1)) {
    c.levels.push_back({w, h, 1});
    if (w == 1 && h == 1) break;
  }
  c.params.minFilter = minF, c.params.magFilter = magF;
  c.params.wrapS = c.params.wrapT = wrap;
  c.params.borderColor = {0.25f, 0.5f, 0.75f, 1.0f};
  return c;
}

const GLenum kMinFilters[] = {GL_NEAREST,
                              GL_LINEAR,
                              GL_NEAREST_MIPMAP_NEAREST,
                              GL_LINEAR_MIPMAP_NEAREST,
                              GL_NEAREST_MIPMAP_LINEAR,
                              GL_LINEAR_MIPMAP_LINEAR};

// Affine minification at several scales and skews: one level of detail per
// draw, across magnification, the switch-over and every level.
TEST(SamplerMesa, MipmapsAffineEveryFilter) {
  const float scales[] = {0.375f, 0.75f, 1.0f, 1.25f, 1.5f, 2.0f, 2.75f, 3.5f, 6.0f, 11.0f, 40.0f};
  int pixels = 0;
  for (GLenum minF : kMinFilters)
    for (GLenum magF : {GL_NEAREST, GL_LINEAR})
      for (float k : scales) {
        Case c = mipmapped2d(GL_RGBA, 32, minF, magF, GL_REPEAT);
        c.width = c.height = 16;
        c.s = {0.125f, k / 32, k / 128};
        c.t = {-0.0625f, -k / 256, k * 3 / 64};
        SCOPED_TRACE(testing::Message() << "min " << minF << " mag " << magF << " scale " << k);
        pixels += compareWithMesa(c);
      }
  RecordProperty("pixels", pixels);
}

// Perspective: q varies across the window, so the level of detail changes
// from quad to quad (the projective division and the per-quad lod).
TEST(SamplerMesa, MipmapsProjectiveEveryFilterAndWrap) {
  int pixels = 0;
  for (GLenum minF : kMinFilters)
    for (GLenum magF : {GL_NEAREST, GL_LINEAR})
      for (GLenum wrap : {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER})
        for (int size : {64, 48}) {
          Case c = mipmapped2d(GL_RGBA, size, minF, magF, wrap);
          c.s = {-0.25f, 1.0f / 64, 1.0f / 256};
          c.t = {0.0625f, 1.0f / 512, 1.0f / 16};
          c.q = {0.25f, 1.0f / 128, 1.0f / 32};
          SCOPED_TRACE(testing::Message()
                       << "min " << minF << " mag " << magF << " wrap " << wrap << " size " << size);
          pixels += compareWithMesa(c);
        }
  RecordProperty("pixels", pixels);
}

// GL_TEXTURE_LOD_BIAS (object and unit), GL_TEXTURE_MIN_LOD / MAX_LOD,
// GL_TEXTURE_BASE_LEVEL / MAX_LEVEL.
TEST(SamplerMesa, MipmapsLodParameters) {
  struct Params {
    float bias, unitBias, minLod, maxLod;
    int base, maxLevel;
  };
  const Params params[] = {
      {0.5f, 0, -1000, 1000, 0, 1000},  {0, -0.75f, -1000, 1000, 0, 1000}, {0.3f, 0.4f, -1000, 1000, 0, 1000},
      {-2.2f, 0, -1000, 1000, 0, 1000}, {0, 0, 1.5f, 1000, 0, 1000},       {0, 0, -1000, 2.25f, 0, 1000},
      {0, 0, 1.0f, 3.0f, 0, 1000},      {0, 0, 2.0f, 2.0f, 0, 1000},       {0, 0, -0.5f, 0.5f, 0, 1000},
      {0, 0, -1000, 1000, 2, 1000},     {0, 0, -1000, 1000, 0, 2},         {0, 0, -1000, 1000, 1, 3},
      {1.0f, 0, 0.5f, 4.0f, 1, 4},      {0, 0, 3.0f, 1.0f, 0, 1000},       {0, 0, -1000, 1000, 3, 2}};
  int pixels = 0;
  for (const Params& pr : params)
    for (GLenum minF : {GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                        GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR})
      for (GLenum magF : {GL_NEAREST, GL_LINEAR}) {
        Case c = mipmapped2d(GL_RGBA, 64, minF, magF, GL_REPEAT);
        c.s = {-0.25f, 1.0f / 64, 1.0f / 256};
        c.t = {0.0625f, 1.0f / 512, 1.0f / 16};
        c.q = {0.25f, 1.0f / 128, 1.0f / 32};
        c.params.lodBias = pr.bias, c.unitLodBias = pr.unitBias;
        c.params.minLod = pr.minLod, c.params.maxLod = pr.maxLod;
        c.params.baseLevel = pr.base, c.params.maxLevel = pr.maxLevel;
        SCOPED_TRACE(testing::Message()
                     << "min " << minF << " mag " << magF << " bias " << pr.bias << " unit " << pr.unitBias
                     << " lod [" << pr.minLod << ", " << pr.maxLod << "] levels [" << pr.base << ", "
                     << pr.maxLevel << "]");
        pixels += compareWithMesa(c);
      }
  RecordProperty("pixels", pixels);
}

// The 8-bit formats other than RGBA8 (luminance, alpha, intensity, ...),
// on both paths (GL_CLAMP_TO_BORDER takes the float path).
TEST(SamplerMesa, EightBitFormatsBothPaths) {
  int pixels = 0;
  for (GLenum format : {GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_INTENSITY, GL_LUMINANCE_ALPHA})
    for (GLenum wrap : {GL_REPEAT, GL_CLAMP_TO_BORDER, GL_CLAMP})
      for (GLenum minF : {GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR}) {
        Case c = mipmapped2d(format, 16, minF, GL_LINEAR, wrap);
        c.params.borderColor = {0.2f, 0.6f, 0.9f, 0.4f};
        c.s = {-0.25f, 1.0f / 64, 1.0f / 256};
        c.t = {-0.0625f, 1.0f / 512, 1.0f / 16};
        c.q = {0.5f, 1.0f / 128, 1.0f / 64};
        SCOPED_TRACE(testing::Message() << "format " << format << " wrap " << wrap << " min " << minF);
        pixels += compareWithMesa(c);
      }
  RecordProperty("pixels", pixels);
}

Case mipmapped(GLenum target, int w, int h, int d, GLenum minF, GLenum magF, GLenum wrap) {
  Case c;
  c.target = target;
  for (;;) {
    c.levels.push_back({w, h, d});
    if (w == 1 && h == 1 && d == 1) break;
    w = std::max(w / 2, 1), h = std::max(h / 2, 1), d = std::max(d / 2, 1);
  }
  c.params.minFilter = minF, c.params.magFilter = magF;
  c.params.wrapS = c.params.wrapT = c.params.wrapR = wrap;
  c.params.borderColor = {0.25f, 0.5f, 0.75f, 1.0f};
  return c;
}

TEST(SamplerMesa, OneDimensional) {
  int pixels = 0;
  for (GLenum minF : kMinFilters)
    for (GLenum magF : {GL_NEAREST, GL_LINEAR})
      for (GLenum wrap : {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_MIRRORED_REPEAT})
        for (int size : {64, 20}) {
          Case c = mipmapped(GL_TEXTURE_1D, size, 1, 1, minF, magF, wrap);
          c.s = {-0.25f, 1.0f / 64, 1.0f / 256};
          c.q = {0.25f, 1.0f / 128, 1.0f / 32};
          SCOPED_TRACE(testing::Message()
                       << "min " << minF << " mag " << magF << " wrap " << wrap << " size " << size);
          pixels += compareWithMesa(c);
        }
  RecordProperty("pixels", pixels);
}

TEST(SamplerMesa, ThreeDimensional) {
  int pixels = 0;
  for (GLenum minF : kMinFilters)
    for (GLenum magF : {GL_NEAREST, GL_LINEAR})
      for (GLenum wrap : {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER}) {
        Case c = mipmapped(GL_TEXTURE_3D, 16, 8, 4, minF, magF, wrap);
        c.s = {-0.25f, 1.0f / 64, 1.0f / 256};
        c.t = {0.0625f, 1.0f / 512, 1.0f / 16};
        c.r = {0.125f, 1.0f / 32, -1.0f / 128};
        c.q = {0.25f, 1.0f / 128, 1.0f / 32};
        SCOPED_TRACE(testing::Message() << "min " << minF << " mag " << magF << " wrap " << wrap);
        pixels += compareWithMesa(c);
      }
  RecordProperty("pixels", pixels);
}

TEST(SamplerMesa, CubeMapFaces) {
  // Directions sweeping across faces: s and t vary, r fixed per case.
  const Affine dirs[][3] = {
      {{-1.5f, 3.0f / 64, 0}, {-1.25f, 0, 2.5f / 64}, {1.0f, 0, 0}},
      {{1.0f, 0, 0}, {-1.5f, 3.0f / 64, 0}, {-1.25f, 0, 2.5f / 64}},
      {{-1.25f, 0, 2.5f / 64}, {-1.0f, 0, 0}, {-1.5f, 3.0f / 64, 0}},
      {{-0.75f, 1.0f / 64, 1.0f / 256}, {-0.5f, 1.0f / 512, 1.0f / 32}, {-0.5f, 1.0f / 128, -1.0f / 256}},
  };
  int pixels = 0;
  for (GLenum minF : kMinFilters)
    for (GLenum magF : {GL_NEAREST, GL_LINEAR})
      for (GLenum wrap : {GL_CLAMP_TO_EDGE, GL_REPEAT})
        for (const auto& d : dirs) {
          Case c = mipmapped(GL_TEXTURE_CUBE_MAP, 16, 16, 1, minF, magF, wrap);
          c.s = d[0], c.t = d[1], c.r = d[2];
          SCOPED_TRACE(testing::Message() << "min " << minF << " mag " << magF << " wrap " << wrap);
          pixels += compareWithMesa(c);
        }
  RecordProperty("pixels", pixels);
}

// Depth textures (GL_DEPTH_COMPONENT16/24/32): the depth itself and
// GL_COMPARE_R_TO_TEXTURE with every function, nearest and linear, through
// every GL_DEPTH_TEXTURE_MODE. r runs past [0, 1] (the reference is clamped)
// and q varies (the reference is r / q).
TEST(SamplerMesa, DepthTexturesCompareAndModes) {
  const GLenum funcs[] = {GL_LEQUAL, GL_GEQUAL,   GL_LESS,   GL_GREATER,
                          GL_EQUAL,  GL_NOTEQUAL, GL_ALWAYS, GL_NEVER};
  int pixels = 0;
  for (GLenum internal : {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32})
    for (GLenum mode : {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA})
      for (GLenum filter : {GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR})
        for (int f = -1; f < 8; ++f) {
          if (mode != GL_LUMINANCE && f > 1) continue;
          Case c = mipmapped2d(GL_RGBA, 16, filter, filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR,
                               GL_CLAMP_TO_EDGE);
          c.width = c.height = 32;
          c.depthInternalFormat = internal;
          c.params.depthTextureMode = mode;
          if (f >= 0) c.params.compareMode = GL_COMPARE_R_TO_TEXTURE, c.params.compareFunc = funcs[f];
          c.s = {-0.125f, 1.0f / 32, 1.0f / 256};
          c.t = {0.0625f, 1.0f / 512, 1.0f / 32};
          c.r = {-0.25f, 1.0f / 64, 1.0f / 32};
          c.q = {0.75f, 1.0f / 128, 1.0f / 64};
          SCOPED_TRACE(testing::Message() << "internal " << internal << " mode " << mode << " filter "
                                          << filter << " func " << (f >= 0 ? funcs[f] : 0));
          pixels += compareWithMesa(c);
        }
  RecordProperty("pixels", pixels);
}

}  // namespace
}  // namespace glfixed::texture
