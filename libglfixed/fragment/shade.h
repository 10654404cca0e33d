// The fragment stage: every fragment of a set-up primitive (raster/
// primitive_setup.h) through the per-fragment operations, in blocks of two
// 2x2 quads (fragment/lanes.h), as llvmpipe shades them. Triangles, lines and
// points all end here.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "fragment/alpha_test_state.h"
#include "fragment/blend_state.h"
#include "fragment/fog_state.h"

#include "fragment/depth_image_state.h"
#include "fragment/stencil_state.h"
#include "framebuffer/framebuffer.h"
#include "raster/primitive_setup.h"
#include "raster/raster.h"

namespace glfixed::fragment {

struct TextureStage;  // fragment/texture_stage.h

// What a primitive's fragments are shaded with, fixed for the primitive: the
// per-fragment state (which operations run, the key) and where they write.
struct ShadeTarget {
  int width = 0, height = 0;
  // llvmpipe row py is GL row py (a framebuffer object), else height - 1 - py.
  bool rowsUp = false;
  // colour
  const ColorBuffer* color = nullptr;
  int bytesPerPixel = 4, red = 0, green = 1, blue = 2, alpha = 3;
  bool colorWrite[4] = {true, true, true, true};
  bool anyColor = true, allColor = true;
  // Fragment colours clamped to [0, 1]: always but on a float buffer, where
  // only OSMesaColorClamp(GL_TRUE) clamps them (fragment/wide_color.inc).
  bool clampColor = true;
  // depth (bits 0: no depth test)
  int depthBits = 0;
  void* depth = nullptr;  // row-major, GL rows, `depthWidth` values a row
  int depthWidth = 0;
  bool depthWrite = true;
  GLenum depthFunc = GL_LESS;
  bool depthClamp = false;  // ARB_depth_clamp
  float depthClampMin = 0, depthClampMax = 1;
  // The depth test after the colour (llvmpipe's late depth test, when the
  // fragment's colour can discard it: the alpha test), else before it.
  bool lateDepth = false;
  AlphaTestState alphaTest;  // GL 2.1 §4.1.4, on the colour's alpha byte
  // The stencil test (GL 2.1 §4.1.5) of the primitive's face, run with the
  // depth test in one step (fragment/stencil.inc).
  StencilTarget stencil;
  bool secondary = false;  // colour sum: add varyings 4..6 to 0..2 (GL 2.1 §3.9)
  // The polygon stipple the fragments pass (null: none): the setup's
  // (triangles), or the state's for every primitive while Mesa's stipple
  // shader stays bound (RasterState::stippleEveryPrimitive).
  const uint32_t* stipple = nullptr;
  // Texturing and the texture environments (null: no unit textures).
  const TextureStage* textures = nullptr;
  // Blending or the logic op (GL 2.1 §4.1.8, §4.1.10), before the colour mask.
  BlendState blend;
  // Fog (GL 2.1 §3.10), after texturing and the colour sum, before the alpha
  // test (fragment/fog.inc); the fog distance is varying raster::kFogVarying.
  FogState fog;

  // glDrawPixels(GL_DEPTH_COMPONENT): the depth comes from the image.
  DepthImageState depthImage;

  // Occlusion query: the counter of fragments past the depth test (null: none).
  uint64_t* samplesPassed = nullptr;
};

ShadeTarget makeShadeTarget(const raster::RasterState& state, Framebuffer& fb,
                            const raster::PrimitiveSetup& t);

// Shades every fragment of the primitive (the AVX2 build of the block shader
// where the CPU has it, else the generic one: the same bits).
void shadePrimitive(const raster::RasterState& state, Framebuffer& fb, const raster::PrimitiveSetup& t);

// The two builds, for tests. Call the AVX2 one only when haveAvx2Fma().
bool haveAvx2Fma();
void shadePrimitiveGeneric(const raster::PrimitiveSetup& t, const ShadeTarget& s);
void shadePrimitiveAvx2(const raster::PrimitiveSetup& t, const ShadeTarget& s);

}  // namespace glfixed::fragment
