// Per-light constants derived from the lighting state when it changes (not per
// vertex): rebuilt by Context::validate() when kDirtyLighting is set. The values
// and the order they are computed in are Mesa's (light.c, prog_statevars.c),
// single precision, because llvmpipe reads exactly these constants.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "state/attribs.h"
#include "state/lighting_attrib.h"
#include "vertex/lighting_matrix.h"

namespace glfixed::vertex {

// Material components, one bit each per face: which ones follow the current
// colour (glColorMaterial), and which ones glMaterial set between glBegin and
// glEnd (LightingAttrib::beginEndMaterialMask).
enum MaterialBit : uint32_t {
  kTrackEmission = 1u << 0,
  kTrackAmbient = 1u << 1,
  kTrackDiffuse = 1u << 2,
  kTrackSpecular = 1u << 3,
  kMaterialShininess = 1u << 4,  // never tracked by glColorMaterial
  kFaceMaterialBits = 0x1fu,
  kTrackBackShift = 5,  // the back face's bits are the front's << 5
};

// The bits glColorMaterial(face, mode) selects; 0 for an invalid pair.
uint32_t colorMaterialBits(GLenum face, GLenum mode);

// One enabled light, in eye space.
struct LightConstants {
  int index = 0;               // GL_LIGHT0 + index
  bool positional = false;     // w != 0 (GL 2.1 §2.14.1: a local light)
  bool spot = false;           // cutoff != 180
  bool attenuated = false;     // (k0, k1, k2) != (1, 0, 0); used for local lights only
  glm::vec3 position{0};       // local: xyz / w (eye space)
  glm::vec3 eyeDirection{0};   // directional: the stored eye position, not normalised
  glm::vec3 direction{0};      // directional: normalize(position), the VP vector
  glm::vec3 halfVector{0};     // directional: normalize(direction + (0, 0, 1))
  glm::vec3 spotDirection{0};  // normalised (twice, as Mesa does)
  float spotCosCutoff = 0;     // max(cos(cutoff), 0)
  float spotExponent = 0;
  float directionalSpotFactor = 1;  // directional spot: the constant spot factor
  glm::vec3 attenuation{1, 0, 0};
  glm::vec3 ambient{0}, diffuse{0}, specular{0};  // the light's colours
};

struct LightingConstants {
  int lightCount = 0;
  std::array<LightConstants, kMaxLights> lights;  // enabled lights, in GL_LIGHTi order

  glm::vec4 modelAmbient{0.2f, 0.2f, 0.2f, 1.0f};
  bool twoSide = false;
  bool separateSpecular = false;
  bool localViewer = false;
  bool normalize = false;      // GL_NORMALIZE
  bool rescaleNormal = false;  // GL_RESCALE_NORMAL
  uint32_t colorMaterial = 0;  // ColorMaterialBit mask while GL_COLOR_MATERIAL is on, else 0

  // Mesa lights in object space when nothing needs eye coordinates (directional,
  // non-spot lights, infinite viewer, single colour) and the modelview preserves
  // lengths (light.c, _mesa_update_lighting / _mesa_update_tnl_spaces).
  bool lightsAllowObjectSpace = false;
  // Texture coordinates (issue 14): texgen needed eye coordinates when these
  // were built (Context::validate then clears lightsAllowObjectSpace).
  bool texgenNeedsEyeCoords = false;

  // A new value, unique in the process, for every rebuild: caches derived from
  // the constants compare it.
  uint64_t generation = 0;
};

void buildLightingConstants(const LightingAttrib& lighting, const TransformAttrib& transform,
                            LightingConstants& out);

// The part of the constants that depends on the modelview too: the space
// lighting happens in and the light vectors in that space. Cached by the
// lighting stage per (constants generation, modelview).
struct LightingSpace {
  bool objectSpace = false;
  // Eye space: n_eye[i] = dot(n, normalFromObject[i]); normalFromObject[i] is
  // row i of the inverse transpose, that is column i of Mesa's inverse.
  glm::mat3 normalFromObject{1};
  float normalRescale = 1.0f;
  struct Light {
    glm::vec3 direction{0}, halfVector{0};
  };
  std::array<Light, kMaxLights> lights;  // directional lights' VP and half vectors in that space
};

void buildLightingSpace(const LightingConstants& constants, const glm::mat4& modelview, LightingSpace& out);

}  // namespace glfixed::vertex
