// The texturing of one draw, as the fragment stage reads it (GL 2.1
// §3.8.15-3.8.16): the units that texture, in unit order, each with the
// view its sampler reads and its environment. Built once per draw from the
// context (pipeline/draw.cpp); the fragment stage never reads the context.
#pragma once

#include "fragment/texture_env.h"
#include "texture/sampler.h"

namespace glfixed::fragment {

struct TextureStage {
  struct Unit {
    int unit = 0;
    texture::SamplerView view;
    TexEnvUnit env;
    // Where the vertices carry no coordinates for the unit
    // (RasterState::texCoordUnits): Mesa's fixed-function fragment shader
    // then reads the current texture coordinates as a constant
    // (ff_fragment_shader.cpp, filter_fp_input_mask: a coordinate varies only
    // with texgen, a texture matrix, or per-vertex data).
    float currentCoord[4] = {0, 0, 0, 1};
    // currentCoord at every fragment even where the vertices carry unit
    // coordinates (a pixel rectangle's: pipeline/pixel_rect.cpp).
    bool constantCoord = false;
  };
  int unitCount = 0;
  Unit units[kMaxTextureEnvUnits];
  // glDrawPixels and glCopyPixels: the image, sampled at unit 0's
  // interpolated coordinates, through `image.env` (GL_REPLACE) before the
  // units: its texel is the fragment's primary colour, as Mesa's
  // nir_lower_drawpixels puts the sample in place of gl_Color.
  bool hasImage = false;
  Unit image;
};

}  // namespace glfixed::fragment
