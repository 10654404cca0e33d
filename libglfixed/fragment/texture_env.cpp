// The texture environment as Mesa's fixed-function fragment shader computes
// it (main/ff_fragment_shader, main/texstate.c) and llvmpipe runs it: in
// single-precision float, one operation at a time, no multiply-add fused
// (llvmpipe's NIR options lower ffma and flrp), in the order below. The
// facts, and the probe that shows them, are in reference/MESA_FACTS.md
// ("Textures: environment"); tests/fragment/texture_env_test.cpp runs the
// probe on Mesa and compares every case bit for bit.
#include "fragment/texture_env.h"

#include <array>

namespace glfixed::fragment {

namespace {

constexpr GLenum kDot3RgbExt = 0x8740, kDot3RgbaExt = 0x8741;  // EXT_texture_env_dot3

// One unit's combiner. A legacy mode (REPLACE, MODULATE, DECAL, BLEND, ADD)
// is restated as a combiner first, per base format, the way Mesa's texstate.c
// does: which decides, for example, that GL_DECAL on an RGBA texture is
// INTERPOLATE(texture, previous, texture alpha).
struct Combiner {
  GLenum modeRGB = GL_MODULATE, modeAlpha = GL_MODULATE;
  std::array<GLenum, 3> sourceRGB{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> sourceAlpha{GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  std::array<GLenum, 3> operandRGB{GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  std::array<GLenum, 3> operandAlpha{GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgbScale = 1, alphaScale = 1;
};

Combiner legacyCombiner(GLenum mode, GLenum format) {
  Combiner c;  // sources texture, previous, constant; operands colour, colour, alpha
  if (format == GL_ALPHA) c.sourceRGB[0] = GL_PREVIOUS;
  if (format == GL_LUMINANCE || format == GL_RGB) c.sourceAlpha[0] = GL_PREVIOUS;
  GLenum modeRGB = mode, modeAlpha = mode;
  switch (mode) {
    case GL_REPLACE:
    case GL_MODULATE: break;
    case GL_DECAL:  // undefined for A, L, LA, I (§3.8.13): Mesa keeps the fragment's colour
      modeRGB = GL_INTERPOLATE;
      modeAlpha = GL_REPLACE;
      c.sourceAlpha[0] = GL_PREVIOUS;
      if (format == GL_RGB)
        modeRGB = GL_REPLACE;
      else if (format == GL_RGBA)
        c.sourceRGB[2] = GL_TEXTURE;
      else
        c.sourceRGB[0] = GL_PREVIOUS;
      break;
    case GL_BLEND:
      modeRGB = GL_INTERPOLATE;
      modeAlpha = GL_MODULATE;
      if (format == GL_ALPHA) {
        modeRGB = GL_REPLACE;
        break;
      }
      if (format == GL_INTENSITY) {
        modeAlpha = GL_INTERPOLATE;
        c.sourceAlpha[0] = GL_CONSTANT;
        c.operandAlpha[2] = GL_SRC_ALPHA;
      }
      c.sourceRGB[2] = GL_TEXTURE;
      c.sourceAlpha[2] = GL_TEXTURE;
      c.sourceRGB[0] = GL_CONSTANT;
      c.operandRGB[2] = GL_SRC_COLOR;
      break;
    case GL_ADD: modeAlpha = format == GL_INTENSITY ? GL_ADD : GL_MODULATE; break;
    default: break;
  }
  // A term whose first source is the previous colour passes it on.
  c.modeRGB = c.sourceRGB[0] == GL_PREVIOUS ? GL_REPLACE : modeRGB;
  c.modeAlpha = c.sourceAlpha[0] == GL_PREVIOUS ? GL_REPLACE : modeAlpha;
  return c;
}

Combiner combinerOf(const TexEnvUnit& unit) {
  const TexEnvAttrib& env = unit.env;
  if (env.mode == GL_COMBINE) {
    Combiner c;
    c.modeRGB = env.combineRGB;
    c.modeAlpha = env.combineAlpha;
    c.sourceRGB = env.sourceRGB;
    c.sourceAlpha = env.sourceAlpha;
    c.operandRGB = env.operandRGB;
    c.operandAlpha = env.operandAlpha;
    c.rgbScale = env.rgbScale;
    c.alphaScale = env.alphaScale;
    return c;
  }
  GLenum format = unit.baseFormat == GL_DEPTH_COMPONENT ? unit.depthTextureMode : unit.baseFormat;
  return legacyCombiner(env.mode, format);
}

int argumentCount(GLenum mode) {
  switch (mode) {
    case GL_REPLACE: return 1;
    case GL_INTERPOLATE: return 3;
    default: return 2;
  }
}

// Modes whose result may leave [0,1] are clamped (Mesa's need_saturate):
// all but REPLACE, MODULATE and INTERPOLATE.
bool clamps(GLenum mode) { return mode != GL_REPLACE && mode != GL_MODULATE && mode != GL_INTERPOLATE; }

bool isDot3(GLenum mode) {
  return mode == GL_DOT3_RGB || mode == GL_DOT3_RGBA || mode == kDot3RgbExt || mode == kDot3RgbaExt;
}

float saturate(float v) {  // NIR's fsat lowered to fmin(fmax(v, 0), 1)
  v = v > 0.0f ? v : 0.0f;
  return v < 1.0f ? v : 1.0f;
}

struct Inputs {
  const TexEnvUnit& unit;
  int unitIndex;
  const TexEnvSources& sources;
  const ColorLanes& previous;
  ColorLanes constant;
};

// Source `source` of the combiner, channel `k`, lane `i`. A crossbar source
// whose unit is not enabled (undefined in GL) reads 0, as a newer Mesa's
// ff_fragment_shader has it; Mesa 22.3 sets only its red to 0 and leaves the
// rest undefined (MESA_FACTS.md), which is not matched.
float sourceValue(const Inputs& in, GLenum source, int k, int i) {
  const ColorLanes* lanes = nullptr;
  switch (source) {
    case GL_TEXTURE: lanes = in.sources.texel[in.unitIndex]; break;
    case GL_CONSTANT: lanes = &in.constant; break;
    case GL_PRIMARY_COLOR: lanes = in.sources.primary ? in.sources.primary : &in.previous; break;
    case GL_PREVIOUS: lanes = &in.previous; break;
    default:
      if (source >= GL_TEXTURE0 && source < GL_TEXTURE0 + kMaxTextureEnvUnits)
        lanes = in.sources.texel[source - GL_TEXTURE0];
      break;
  }
  return lanes ? lanes->c[k][i] : 0.0f;
}

// An argument: a source's colour or alpha, or one minus it. NIR keeps 1 - v
// as 1 + -v, so the optimizer may fold it into what uses it (below).
struct Arg {
  float source;  // the source's channel
  bool oneMinus;
  float value() const { return oneMinus ? 1.0f - source : source; }
};

Arg argument(const Inputs& in, GLenum source, GLenum operand, int k, int i) {
  const bool alpha = operand == GL_SRC_ALPHA || operand == GL_ONE_MINUS_SRC_ALPHA;
  const bool oneMinus = operand == GL_ONE_MINUS_SRC_COLOR || operand == GL_ONE_MINUS_SRC_ALPHA;
  return {sourceValue(in, source, alpha ? 3 : k, i), oneMinus};
}

// The combiner function of one channel (not DOT3), as llvmpipe gets it after
// NIR's algebraic optimizer (Mesa 22.3, probed with ST_DEBUG=nir):
// - ADD_SIGNED is written (a0 + a1) + -0.5; the constant moves next to a0,
//   (a0 + -0.5) + a1, and folds into a0's 1 + -v: (0.5 + -v) + a1.
// - INTERPOLATE is flrp(a1, a0, a2), lowered (lower_flrp32, no ffma) to
//   a0 * a2 + a1 * (1 - a2); 1 - (1 - v) folds to v.
// Not matched: when a0 of ADD_SIGNED is the previous unit's unclamped sum,
// NIR moves the -0.5 into that sum, which is out of this unit's sight.
float combine(GLenum mode, const Arg a[3]) {
  switch (mode) {
    case GL_REPLACE: return a[0].value();
    case GL_MODULATE: return a[0].value() * a[1].value();
    case GL_ADD: return a[0].value() + a[1].value();
    case GL_ADD_SIGNED:
      if (a[0].oneMinus) return (0.5f - a[0].source) + a[1].value();
      return (a[0].value() + -0.5f) + a[1].value();
    case GL_INTERPOLATE: {
      const float t = a[2].value(), oneMinusT = a[2].oneMinus ? a[2].source : 1.0f - t;
      return a[0].value() * t + a[1].value() * oneMinusT;
    }
    case GL_SUBTRACT: return a[0].value() - a[1].value();
    default: return a[0].value();
  }
}

// DOT3: 4 * ((r0 - 0.5)(r1 - 0.5) + ...), computed as Mesa writes it: each
// argument as v * 2 + -1, then the dot product, which NIR lowers (lower_fdot)
// from the last component: (b0 b1 + g0 g1) + r0 r1.
float dot3(const Inputs& in, const Combiner& c, int i) {
  float t0[3], t1[3];
  for (int k = 0; k < 3; ++k) {
    t0[k] = argument(in, c.sourceRGB[0], c.operandRGB[0], k, i).value() * 2.0f + -1.0f;
    t1[k] = argument(in, c.sourceRGB[1], c.operandRGB[1], k, i).value() * 2.0f + -1.0f;
  }
  float p0 = t0[0] * t1[0], p1 = t0[1] * t1[1], p2 = t0[2] * t1[2];
  return (p2 + p1) + p0;
}

}  // namespace

void applyTexEnv(const TexEnvUnit& unit, int unitIndex, const TexEnvSources& sources, ColorLanes& previous) {
  const Combiner c = combinerOf(unit);
  Inputs in{unit, unitIndex, sources, previous, {}};
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < kBlockLanes; ++i) in.constant.c[k][i] = unit.env.color[k];

  // The EXT spelling of DOT3 ignores the scales; the ARB one (GL 1.3) applies
  // them. A clamp the scale follows is done once, after it.
  const bool extDot3 = c.modeRGB == kDot3RgbExt || c.modeRGB == kDot3RgbaExt;
  const float rgbScale = extDot3 ? 1.0f : c.rgbScale;
  const float alphaScale = c.modeRGB == kDot3RgbaExt ? 1.0f : c.alphaScale;
  const bool scaled = rgbScale != 1.0f || alphaScale != 1.0f;
  const bool rgbClamp = rgbScale == 1.0f && clamps(c.modeRGB);
  const bool alphaClamp = alphaScale == 1.0f && clamps(c.modeAlpha);
  const bool dot3Alpha = c.modeRGB == GL_DOT3_RGBA || c.modeRGB == kDot3RgbaExt;
  const int rgbArgs = argumentCount(c.modeRGB), alphaArgs = argumentCount(c.modeAlpha);

  ColorLanes result;
  for (int i = 0; i < kBlockLanes; ++i) {
    float rgb[3];
    if (isDot3(c.modeRGB)) {
      float d = dot3(in, c, i);
      if (rgbClamp) d = saturate(d);
      rgb[0] = rgb[1] = rgb[2] = d;
    } else {
      for (int k = 0; k < 3; ++k) {
        Arg a[3] = {};
        for (int n = 0; n < rgbArgs; ++n) a[n] = argument(in, c.sourceRGB[n], c.operandRGB[n], k, i);
        float v = combine(c.modeRGB, a);
        rgb[k] = rgbClamp ? saturate(v) : v;
      }
    }
    float alpha;
    if (dot3Alpha) {
      alpha = rgb[0];  // the dot product, clamped as the colour is
    } else {
      Arg a[3] = {};
      for (int n = 0; n < alphaArgs; ++n) a[n] = argument(in, c.sourceAlpha[n], c.operandAlpha[n], 3, i);
      float v = combine(c.modeAlpha, a);
      alpha = alphaClamp ? saturate(v) : v;
    }
    float out[4] = {rgb[0], rgb[1], rgb[2], alpha};
    if (scaled) {  // one multiply by (rgb, rgb, rgb, alpha) scale, then the clamp
      for (int k = 0; k < 3; ++k) out[k] = saturate(out[k] * rgbScale);
      out[3] = saturate(out[3] * alphaScale);
    }
    for (int k = 0; k < 4; ++k) result.c[k][i] = out[k];
  }
  previous = result;
}

}  // namespace glfixed::fragment
