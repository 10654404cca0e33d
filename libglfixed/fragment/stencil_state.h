// The stencil test's state as the fragment stage runs it (GL 2.1 §4.1.5):
// one face's function, reference, masks and operations, already cut to the
// 8 bits of the stencil buffer, and where the buffer is.
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace glfixed::fragment {

// One face: the reference clamped to [0, 255] (GL 2.1 §4.1.5), the masks
// cut to 8 bits.
struct StencilFaceState {
  GLenum func = GL_ALWAYS;
  int32_t ref = 0;
  int32_t valueMask = 0xff, writeMask = 0xff;
  GLenum fail = GL_KEEP, depthFail = GL_KEEP, depthPass = GL_KEEP;
};

// A draw's stencil state (raster::RasterState): GL_STENCIL_TEST with a
// stencil buffer, and both faces; the primitive's facing picks one.
struct StencilState {
  bool enabled = false;
  StencilFaceState face[2];  // [0] front, [1] back
};

// What a primitive's fragments need (fragment/shade.h, ShadeTarget::stencil).
// `active`: the stencil-and-depth step runs instead of the plain depth step:
// with the stencil test, or with the depth test on a buffer whose depth words
// carry the stencil in their top byte (the depth then compares and writes the
// low 24 bits only).
struct StencilTarget {
  bool active = false;
  bool test = false;    // the stencil test and its operations (else: passes, writes nothing)
  bool writes = false;  // some operation may change a value (write mask and operations)
  StencilFaceState face;
  uint32_t* packed = nullptr;  // the depth words, stencil in the top byte (Z24_UNORM_S8_UINT)
  uint8_t* bytes = nullptr;    // or one byte a pixel (a stencil buffer without depth)
  int width = 0;               // values a row; rows are GL rows, bottom first
};

}  // namespace glfixed::fragment
