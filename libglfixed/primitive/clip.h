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
// User clip planes (§2.12) come after the six, as planes 6..13 (bit 6 + i for
// GL_CLIP_PLANEi), in clip space: Mesa's fixed-function vertex shader writes
// no clip distance, the state tracker hands llvmpipe the eye-space plane
// times the inverse projection (main/clip.c, _mesa_update_clip_plane;
// st_atom_clip.c), and the draw module takes the distances from the clip
// position:
//   - the clip mask bit of a vertex: 0 > fma-chain dot product (generated
//     code, draw_llvm.c generate_clipmask: p.x * c.x, then fused
//     multiply-adds of y, z, w), unordered, so NaN is outside;
//   - the distance the clipper uses (for every vertex, the ones it makes
//     included): the plain C dot product, left to right, unfused
//     (draw_pipe_clip.c, getclipdist). A vertex whose fused distance is
//     below 0 and unfused one is 0 sends its draw through the pipeline but
//     is not cut (probed).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace glfixed::primitive {

// The enabled user clip planes of a draw, in clip space.
constexpr int kMaxUserClipPlanes = 8;
constexpr int kFirstUserClipPlane = 6;  // clip mask bit of GL_CLIP_PLANE0
struct UserClipPlanes {
  uint32_t enabled = 0;  // bit i: GL_CLIP_PLANEi
  std::array<glm::vec4, kMaxUserClipPlanes> plane{};
  // GL_DEPTH_CLAMP: the near and far planes (4, 5) clip nothing.
  bool depthClamp = false;
};
inline const UserClipPlanes kNoUserClipPlanes{};

// Mesa's _mesa_transform_vector: the row vector `plane` times m, each
// component summed left to right in float (m_matrix.c). glClipPlane maps a
// plane to eye space with the inverse modelview; the draw maps it to clip
// space with the inverse projection.
glm::vec4 transformPlane(const glm::vec4& plane, const glm::mat4& m);

// Colours carried through clipping: front primary, front secondary, back
// primary, back secondary (RGBA each); GL_FLAT copies only these.
constexpr int kClipColorAttribs = 16;
// Texture coordinates (issue 14): then s, t, r, q of each carried unit u at
// kClipTexCoordAttribs + 4 u, interpolated like the colours.
constexpr int kClipTexCoordAttribs = kClipColorAttribs;
constexpr int kClipTexCoordUnits = 8;
// Fog: the fog distance, last.
constexpr int kClipFogAttrib = kClipTexCoordAttribs + 4 * kClipTexCoordUnits;
constexpr int kMaxClipAttribs = kClipFogAttrib + 1;

struct ClipVertex {
  glm::vec4 clip{0};     // clip coordinates
  float window[4] = {};  // x, y (down), z, 1/w: see viewport.h
  float attr[kMaxClipAttribs] = {};
  float pointSize = 1;  // points: the per-vertex size (attenuation), interpolated by the clipper
};

// Bit i set: outside plane i (the order above). Comparisons as llvmpipe's
// vertex shader makes them: unordered, so a NaN coordinate is outside all.
uint32_t clipMask(const glm::vec4& clip);
// The same with the bits of the enabled user clip planes (6 + i).
uint32_t clipMask(const glm::vec4& clip, const UserClipPlanes& user);

// Signed distances to the six planes as draw_pipe_clip.c computes them: a
// float dot product with the plane, left to right. Inside: >= 0.
float distanceToRight(const glm::vec4& c);   // plane 0: x <= w
float distanceToLeft(const glm::vec4& c);    // plane 1: -w <= x
float distanceToTop(const glm::vec4& c);     // plane 2: y <= w
float distanceToBottom(const glm::vec4& c);  // plane 3: -w <= y
float distanceToNear(const glm::vec4& c);    // plane 4: -w <= z
float distanceToFar(const glm::vec4& c);     // plane 5: z <= w
float distanceToPlane(int plane, const glm::vec4& c);
// Planes 6.. are the user clip planes of `user` (the unfused dot product).
float distanceToPlane(int plane, const glm::vec4& c, const UserClipPlanes& user);

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
// bits; 6.. from `user`). Returns false when nothing is left; else `result`
// holds a convex polygon of 3 or more vertices.
bool clipTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, uint32_t planes,
                  int attribCount, const struct ViewportTransform& viewport, ClippedPolygon& result,
                  const UserClipPlanes& user = kNoUserClipPlanes);

}  // namespace glfixed::primitive
