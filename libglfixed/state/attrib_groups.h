// The glPushAttrib groups whose stages come later (GL 2.1 §6.1.14, tables
// 6.5-6.37): fog, stencil, scissor, lines, points, polygon stipple, pixel
// mode, accumulation, multisample, texture. Each holds the part of its table
// that is cheap to hold now, with the initial values of the tables; no setter
// writes them yet, so they push and pop their defaults and glGet/glIsEnabled
// report them. The stage that implements a group writes its setters here.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "state/texgen_attrib.h"
#include "state/texture_binding_attrib.h"
#include "state/texture_env_attrib.h"

namespace glfixed {

constexpr int kMaxTextureUnits = 8;

// GL_FOG_BIT (table 6.10 and the colour sum enable of table 6.11).
struct FogAttrib {
  bool enabled = false;
  bool colorSum = false;
  GLenum mode = GL_EXP;
  glm::vec4 color{0, 0, 0, 0};
  float density = 1, start = 0, end = 1, index = 0;
  GLenum coordSrc = GL_FRAGMENT_DEPTH;
  // NV_fog_distance: how the fog distance of GL_FRAGMENT_DEPTH is measured.
  GLenum distanceMode = 0x855C;  // GL_EYE_PLANE_ABSOLUTE_NV
};

// GL_STENCIL_BUFFER_BIT (table 6.20 and the clear value of table 6.21).
struct StencilAttrib {
  struct Face {
    GLenum func = GL_ALWAYS;
    GLint ref = 0;
    GLuint valueMask = 0xff;  // Mesa's initial masks read 0xff (probed), not all ones
    GLenum fail = GL_KEEP, depthFail = GL_KEEP, depthPass = GL_KEEP;
    GLuint writeMask = 0xff;
    bool operator==(const Face& o) const {
      return func == o.func && ref == o.ref && valueMask == o.valueMask && fail == o.fail &&
             depthFail == o.depthFail && depthPass == o.depthPass && writeMask == o.writeMask;
    }
  };
  bool test = false;
  // Mesa keeps three faces (stencil.c): [0] front; [1] the back face of GL
  // 2.0's Separate commands and ATI_separate_stencil; [2] the back face of
  // EXT_stencil_two_side, which back-facing primitives use while
  // GL_STENCIL_TEST_TWO_SIDE_EXT is on. glStencilFunc, glStencilOp and
  // glStencilMask set [0] and [1], or only [2] while glActiveStencilFaceEXT
  // names GL_BACK (activeFace 2); the plain queries read [activeFace].
  std::array<Face, 3> face;
  // EXT_stencil_two_side's names (not in GL 2.1's gl.h).
  static constexpr GLenum kTestTwoSideEXT = 0x8910;     // GL_STENCIL_TEST_TWO_SIDE_EXT
  static constexpr GLenum kActiveFaceEXT = 0x8911;      // GL_ACTIVE_STENCIL_FACE_EXT
  bool testTwoSide = false;
  int activeFace = 0;  // 0 (GL_FRONT) or 2 (GL_BACK)
  GLint clearValue = 0;
};

// GL_SCISSOR_BIT (table 6.19). The box starts as the size of the first
// drawable, like the viewport (set by OSMesaMakeCurrent).
struct ScissorAttrib {
  bool test = false;
  GLint x = 0, y = 0;
  GLsizei width = 0, height = 0;
};

// GL_LINE_BIT (table 6.15).
struct LineAttrib {
  float width = 1;
  bool smooth = false;
  bool stipple = false;
  GLushort stipplePattern = 0xffff;
  GLint stippleRepeat = 1;
};

// GL_POINT_BIT (table 6.14).
struct PointAttrib {
  float size = 1;
  bool smooth = false;
  bool sprite = false;
  float sizeMin = 0, sizeMax = 255, fadeThresholdSize = 1;  // sizeMax: Mesa's initial value, its largest size
  glm::vec3 distanceAttenuation{1, 0, 0};
  GLenum spriteCoordOrigin = GL_UPPER_LEFT;
  std::array<bool, kMaxTextureUnits> coordReplace{};
};

// GL_POLYGON_STIPPLE_BIT (table 6.17): 32 rows of 32 bits, all set.
struct PolygonStippleAttrib {
  std::array<uint32_t, 32> pattern;
  PolygonStippleAttrib() { pattern.fill(~0u); }
};

// GL_PIXEL_MODE_BIT (tables 6.23-6.24, without the pixel maps and the imaging
// subset's tables, which come with the pixel transfer stage).
struct PixelModeAttrib {
  GLenum readBuffer = GL_FRONT;  // single-buffered OSMesa: the front buffer
  bool mapColor = false, mapStencil = false;
  GLint indexShift = 0, indexOffset = 0;
  glm::vec4 scale{1, 1, 1, 1}, bias{0, 0, 0, 0};  // RED..ALPHA
  float depthScale = 1, depthBias = 0;
  float zoomX = 1, zoomY = 1;
};

// GL_ACCUM_BUFFER_BIT (table 6.21).
struct AccumAttrib {
  glm::vec4 clearValue{0, 0, 0, 0};
};

// GL_MULTISAMPLE_BIT (table 6.16).
struct MultisampleAttrib {
  bool multisample = true;
  bool sampleAlphaToCoverage = false, sampleAlphaToOne = false, sampleCoverage = false;
  float sampleCoverageValue = 1;
  GLboolean sampleCoverageInvert = GL_FALSE;  // as given: Mesa returns 7 for 7
};

// The per-unit enables of table 6.25/6.26: also in GL_ENABLE_BIT, which saves
// every unit's (not only the active one's).
struct TextureUnitEnables {
  bool texture1D = false, texture2D = false, texture3D = false, textureCubeMap = false;
  bool genS = false, genT = false, genR = false, genQ = false;
  bool operator==(const TextureUnitEnables& o) const {
    return texture1D == o.texture1D && texture2D == o.texture2D && texture3D == o.texture3D &&
           textureCubeMap == o.textureCubeMap && genS == o.genS && genT == o.genT && genR == o.genR &&
           genQ == o.genQ;
  }
};

// GL_TEXTURE_BIT (tables 6.25-6.27): per unit, the enables, the bound
// texture names, the environment and texgen. Each part has its own header,
// owned by the stage that uses it.
struct TextureAttrib {
  GLenum activeTexture = GL_TEXTURE0;
  std::array<TextureUnitEnables, kMaxTextureUnits> enables;
  std::array<TextureBindings, kMaxTextureUnits> binding;
  std::array<TexEnvAttrib, kMaxTextureUnits> env;
  std::array<TexGenAttrib, kMaxTextureUnits> texgen;
  int activeUnit() const { return static_cast<int>(activeTexture - GL_TEXTURE0); }
  TextureUnitEnables& activeEnables() { return enables[activeUnit()]; }
};

}  // namespace glfixed
