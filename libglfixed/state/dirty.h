// Dirty bits: what derived state Context::validate() must rebuild before a draw.
#pragma once

#include <cstdint>

namespace glfixed {

enum DirtyBit : uint32_t {
  kDirtyModelview = 1u << 0,   // eyeFromObject, normal matrix, clipFromObject
  kDirtyProjection = 1u << 1,  // clipFromObject
  kDirtyLighting = 1u << 2,    // lighting constants
  kDirtyAll = ~0u,
};

}  // namespace glfixed
