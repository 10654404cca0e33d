// Clipping in homogeneous space against the six planes of the view volume
// (GL 2.1 §2.12), done as Mesa's draw module does it for llvmpipe
// (draw_pipe_clip.c). Facts that change coverage:
//   - llvmpipe with a depth buffer uses no guard band: a triangle with any
//     vertex outside any of the six planes is clipped against every plane
//     that some vertex is outside of, in plane order: x <= w, -w <= x,
//     y <= w, -w <= y, -w <= z, z <= w (lp_state_derived.c; draw_llvm.c,
//     generate_clipmask). A triangle with all vertices outside one plane is
//     dropped; one with no vertex outside is not touched.
//   - Each plane is a Sutherland-Hodgman pass over the polygon; a new vertex
//     is interpolated from whichever end lies nearer the plane.
//   - A NaN or infinite plane distance drops the whole triangle.
//   - The clipped polygon is fanned from its first vertex (clipPolygonFan).
//   - w <= 0 needs nothing special: such a vertex is outside some plane.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

namespace glfixed::primitive {

// Colours carried through clipping: front primary, front secondary, back
// primary, back secondary (RGBA each).
constexpr int kMaxClipAttribs = 16;

struct ClipVertex {
  glm::vec4 clip{0};     // clip coordinates
  float window[4] = {};  // x, y (down), z, 1/w: see viewport.h
  float attr[kMaxClipAttribs] = {};
  float pointSize = 1;  // points: the per-vertex size (attenuation), interpolated by the clipper
};

// Bit i set: outside plane i (the order above). Comparisons as llvmpipe's
// vertex shader makes them: unordered, so a NaN coordinate is outside all.
uint32_t clipMask(const glm::vec4& clip);

// Signed distances to the six planes as draw_pipe_clip.c computes them: a
// float dot product with the plane, left to right. Inside: >= 0.
float distanceToRight(const glm::vec4& c);   // plane 0: x <= w
float distanceToLeft(const glm::vec4& c);    // plane 1: -w <= x
float distanceToTop(const glm::vec4& c);     // plane 2: y <= w
float distanceToBottom(const glm::vec4& c);  // plane 3: -w <= y
float distanceToNear(const glm::vec4& c);    // plane 4: -w <= z
float distanceToFar(const glm::vec4& c);     // plane 5: z <= w
float distanceToPlane(int plane, const glm::vec4& c);

struct ViewportTransform;

// Room for the clipped polygon of one triangle: Mesa's limit,
// 2 * (6 + 8 user planes) + 1 vertices.
constexpr int kMaxClippedVertices = 29;

struct ClippedPolygon {
  const ClipVertex* vertex[kMaxClippedVertices + 1] = {};
  int count = 0;
  ClipVertex created[kMaxClippedVertices + 1];  // the vertices clipping made
  int createdCount = 0;
};

// The vertex on segment out -> in at parameter t: out + t * (in - out) for the
// clip position and every one of `attribCount` attributes, then mapped to
// window space (unfused, as the clipper does).
void interpolateClipVertex(const ClipVertex& out, const ClipVertex& in, float t, int attribCount,
                           const struct ViewportTransform& viewport, ClipVertex& dst);

// Clips triangle (v0, v1, v2) against every plane in `planes` (clip mask
// bits). Returns false when nothing is left; else `result` holds a convex
// polygon of 3 or more vertices.
bool clipTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, uint32_t planes,
                  int attribCount, const struct ViewportTransform& viewport, ClippedPolygon& result);

}  // namespace glfixed::primitive
