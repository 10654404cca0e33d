// The fragment stage's two builds of the one block shader (block_shader.inc):
// for any x86-64 CPU, and with AVX2 and FMA; shadePrimitive picks the second
// where the CPU has it. Both give the same bits (tests/fragment/shade_test.cpp).
#pragma GCC optimize("fp-contract=off")
#pragma GCC diagnostic ignored "-Wpsabi"

#include "fragment/shade.h"

#include <GL/gl.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fragment/blend_state.h"
#include "fragment/isa.h"
#include "fragment/texture_stage.h"
#include "raster/depth.h"
#include "raster/edge.h"
#include "raster/interpolate.h"
#include "raster/primitive_setup.h"

namespace glfixed::fragment {
namespace generic {
#define GLFIXED_BLOCK_AVX2 0
#include "fragment/alpha_test.inc"
#include "fragment/blend.inc"
#include "fragment/depth_image.inc"
#include "fragment/fog.inc"
#include "fragment/wide_color.inc"
// (block_shader.inc last, apart: it uses the files above.)

#include "fragment/block_shader.inc"
#undef GLFIXED_BLOCK_AVX2
}  // namespace generic

#pragma GCC push_options
#pragma GCC target("avx2,fma")
namespace avx2 {
#define GLFIXED_BLOCK_AVX2 1
#include "fragment/alpha_test.inc"
#include "fragment/blend.inc"
#include "fragment/depth_image.inc"
#include "fragment/fog.inc"
#include "fragment/wide_color.inc"
// (block_shader.inc last, apart: it uses the files above.)

#include "fragment/block_shader.inc"
#undef GLFIXED_BLOCK_AVX2
}  // namespace avx2
#pragma GCC pop_options

bool haveAvx2Fma() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

void shadePrimitiveGeneric(const raster::PrimitiveSetup& t, const ShadeTarget& s) {
  generic::shadeBlocks(t, s);
}

__attribute__((target("avx2,fma"))) void shadePrimitiveAvx2(const raster::PrimitiveSetup& t,
                                                            const ShadeTarget& s) {
  avx2::shadeBlocks(t, s);
}

AlphaTestState makeAlphaTest(bool enabled, GLenum func, float ref) {
  AlphaTestState a;
  if (!enabled) return a;
  a.func = func;
  a.ref = raster::colorToUnorm8(ref);
  a.refFloat = ref;
  return a;
}

// Mesa's STATE_FOG_PARAMS_OPTIMIZED and its clamped fog colour (fog_state.h).
FogState makeFogState(bool enabled, GLenum mode, float density, float start, float end, const glm::vec4& color) {
  FogState f;
  if (!enabled) return f;
  f.mode = mode == GL_LINEAR ? FogState::Mode::kLinear : (mode == GL_EXP ? FogState::Mode::kExp : FogState::Mode::kExp2);
  f.scale = end == start ? 1.0f : -1.0f / (end - start);
  f.offset = end * -f.scale;
  constexpr double kOneOverLn2 = 1.4426950408889634074, kOneOverSqrtLn2 = 1.201122408786449815;
  f.density = static_cast<float>(double(density) * (mode == GL_EXP ? kOneOverLn2 : kOneOverSqrtLn2));
  for (int k = 0; k < 3; ++k) {
    const float c = color[k];
    f.color[k] = c > 0.0f ? (c > 1.0f ? 1.0f : c) : 0.0f;  // NaN -> 0
  }
  return f;
}

namespace {
const bool kUseAvx2 = haveAvx2Fma();
}  // namespace

ShadeTarget makeShadeTarget(const raster::RasterState& state, Framebuffer& fb,
                            const raster::PrimitiveSetup& t) {
  ShadeTarget s;
  s.width = fb.width();
  s.height = fb.height();
  s.rowsUp = fb.rowsUp();
  s.color = &fb.color;
  s.bytesPerPixel = fb.color.bytesPerPixel;
  s.red = fb.color.red;
  s.green = fb.color.green;
  s.blue = fb.color.blue;
  s.alpha = fb.color.alpha;
  // A framebuffer object without a colour buffer to draw into (draw buffer
  // GL_NONE, a depth-only object) still runs the depth and stencil tests.
  const bool haveColor = fb.color.pixels != nullptr;
  for (int k = 0; k < 4; ++k) s.colorWrite[k] = state.colorWrite[k] && haveColor;
  s.clampColor = !fb.color.floatChannels() || state.clampFragmentColor;
  s.anyColor = s.colorWrite[0] || s.colorWrite[1] || s.colorWrite[2] || s.colorWrite[3];
  s.allColor = s.colorWrite[0] && s.colorWrite[1] && s.colorWrite[2] && s.colorWrite[3];
  if (state.depthTest && fb.depth.bits() != 0) {
    s.depthBits = fb.depth.bits();
    s.depth = fb.depth.data();
    s.depthWidth = fb.depth.width();
    s.depthWrite = state.depthWrite;
    s.depthFunc = state.depthFunc;
    s.depthClamp = state.depthClamp;
    s.depthClampMin = state.depthClampMin;
    s.depthClampMax = state.depthClampMax;
  }
  // The stencil test of the primitive's face; on a Z24S8 buffer the depth
  // test too goes through the stencil step, which keeps the stencil byte.
  DepthBuffer& db = fb.depth;
  if (db.stencilBits() && (state.stencil.enabled || (state.depthTest && db.packedStencil()))) {
    StencilTarget& st = s.stencil;
    st.active = true;
    st.test = state.stencil.enabled;
    if (st.test) {
      st.face = state.stencil.face[t.backFacing ? 1 : 0];
      const StencilFaceState& f = st.face;
      st.writes = f.writeMask != 0 && (f.fail != GL_KEEP || f.depthFail != GL_KEEP || f.depthPass != GL_KEEP);
    }
    st.packed = db.packedStencil() ? static_cast<uint32_t*>(db.data()) : nullptr;
    st.bytes = db.packedStencil() ? nullptr : db.stencil8();
    st.width = db.width();
  }
  s.secondary = t.varyingCount == 8;
  s.stipple = t.stipple ? t.stipple : (state.stippleEveryPrimitive ? state.polygonStipple : nullptr);
  s.textures = state.textures && (state.textures->unitCount > 0 || state.textures->hasImage) ? state.textures : nullptr;
  s.blend = state.blend;
  s.fog = t.fog ? state.fog : FogState();  // only where the vertices carried the fog distance
  s.alphaTest = state.alphaTest;
  s.depthImage = state.depthImage;
  s.samplesPassed = state.samplesPassed;
  // The alpha test can discard after the colour: llvmpipe then tests depth late.
  if (s.alphaTest.active()) s.lateDepth = true;
  return s;
}

void shadePrimitive(const raster::RasterState& state, Framebuffer& fb, const raster::PrimitiveSetup& t) {
  const ShadeTarget target = makeShadeTarget(state, fb, t);
  if (kUseAvx2)
    shadePrimitiveAvx2(t, target);
  else
    shadePrimitiveGeneric(t, target);
}

}  // namespace glfixed::fragment
