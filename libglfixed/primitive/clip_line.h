// Line clipping against the view volume as Mesa's draw module does it for
// llvmpipe (draw_pipe_clip.c, clip_line and do_clip_line): no guard band for
// lines in desktop GL, so a line with an end outside any plane is clipped.
#pragma once

#include <cstdint>

#include "primitive/clip.h"

namespace glfixed::primitive {

struct ViewportTransform;

// The visible part of line v0 -> v1, whose clip masks are m0 and m1, with
// m0 & m1 == 0 and m0 | m1 != 0. For each plane of `planes` (clip mask bits,
// in bit order) each end outside gets t = d_end / (d_end - d_other), the
// largest t kept per end; the line is dropped when t0 + t1 >= 1 or a plane
// distance is NaN or infinite. An end that was outside is moved to
// end + t * (other - end), every one of `attribCount` attributes
// interpolated the same way, its window position recomputed unfused
// (viewport.h). Under GL_FLAT (`flat`) a moved end takes `provoking`'s
// attributes instead (copy_flat). Returns false when nothing is left; else
// *out0 and *out1 point at the ends (the inputs or `made`).
bool clipLine(const ClipVertex& v0, const ClipVertex& v1, uint32_t m0, uint32_t m1, uint32_t planes,
              int attribCount, const ViewportTransform& viewport, bool flat, const ClipVertex& provoking,
              ClipVertex made[2], const ClipVertex** out0, const ClipVertex** out1);

}  // namespace glfixed::primitive
