// Every float operation here must round exactly as llvmpipe's does: forbid
// contracting a * b + c into a fused multiply-add (GCC contracts by default
// in C++ whenever the target has FMA).
#pragma GCC optimize("fp-contract=off")

#include "primitive/clip.h"

#include <cmath>

#include "primitive/viewport.h"

namespace glfixed::primitive {

namespace {

// draw_pipe_clip.c's dot4, in float, left to right. The zero coefficients
// matter only for infinities (inf * 0 = NaN drops the triangle).
inline float dot4(const glm::vec4& c, float a, float b, float d, float e) {
  float s = c.x * a + c.y * b;
  s = s + c.z * d;
  return s + c.w * e;
}

inline bool isInfOrNan(float v) { return !std::isfinite(v); }

}  // namespace

uint32_t clipMask(const glm::vec4& c) {
  // "outside" is the negation of an ordered "inside" test, so NaN is outside.
  uint32_t m = 0;
  if (!(c.x <= c.w)) m |= 1u << 0;
  if (!(0.0f <= c.x + c.w)) m |= 1u << 1;
  if (!(c.y <= c.w)) m |= 1u << 2;
  if (!(0.0f <= c.y + c.w)) m |= 1u << 3;
  if (!(0.0f <= c.z + c.w)) m |= 1u << 4;
  if (!(c.z <= c.w)) m |= 1u << 5;
  return m;
}

float distanceToRight(const glm::vec4& c) { return dot4(c, -1, 0, 0, 1); }
float distanceToLeft(const glm::vec4& c) { return dot4(c, 1, 0, 0, 1); }
float distanceToTop(const glm::vec4& c) { return dot4(c, 0, -1, 0, 1); }
float distanceToBottom(const glm::vec4& c) { return dot4(c, 0, 1, 0, 1); }
float distanceToNear(const glm::vec4& c) { return dot4(c, 0, 0, 1, 1); }
float distanceToFar(const glm::vec4& c) { return dot4(c, 0, 0, -1, 1); }

glm::vec4 transformPlane(const glm::vec4& v, const glm::mat4& m) {
  glm::vec4 u;
  for (int j = 0; j < 4; ++j) u[j] = ((v[0] * m[j][0] + v[1] * m[j][1]) + v[2] * m[j][2]) + v[3] * m[j][3];
  return u;
}

uint32_t clipMask(const glm::vec4& c, const UserClipPlanes& user) {
  uint32_t m = clipMask(c);
  if (user.depthClamp) m &= ~((1u << 4) | (1u << 5));
  for (uint32_t planes = user.enabled; planes != 0; planes &= planes - 1) {
    const int i = __builtin_ctz(planes);
    const glm::vec4& p = user.plane[i];
    float d = p.x * c.x;
    d = std::fma(p.y, c.y, d);
    d = std::fma(p.z, c.z, d);
    d = std::fma(p.w, c.w, d);
    if (!(0.0f <= d)) m |= 1u << (kFirstUserClipPlane + i);
  }
  return m;
}

float distanceToPlane(int plane, const glm::vec4& c, const UserClipPlanes& user) {
  if (plane < kFirstUserClipPlane) return distanceToPlane(plane, c);
  const glm::vec4& p = user.plane[plane - kFirstUserClipPlane];
  return dot4(c, p.x, p.y, p.z, p.w);
}

float distanceToPlane(int plane, const glm::vec4& c) {
  switch (plane) {
    case 0: return distanceToRight(c);
    case 1: return distanceToLeft(c);
    case 2: return distanceToTop(c);
    case 3: return distanceToBottom(c);
    case 4: return distanceToNear(c);
    default: return distanceToFar(c);
  }
}

void interpolateClipVertex(const ClipVertex& out, const ClipVertex& in, float t, int attribCount,
                           const ViewportTransform& viewport, ClipVertex& dst) {
  for (int i = 0; i < 4; ++i) {
    float d = in.clip[i] - out.clip[i];
    dst.clip[i] = out.clip[i] + t * d;
  }
  for (int i = 0; i < attribCount; ++i) {
    float d = in.attr[i] - out.attr[i];
    dst.attr[i] = out.attr[i] + t * d;
  }
  // Points: the clipper interpolates the point size output too.
  dst.pointSize = out.pointSize + t * (in.pointSize - out.pointSize);
  viewport.windowFromClipUnfused(dst.clip, dst.window);
}

bool clipTriangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, uint32_t planes,
                  int attribCount, const ViewportTransform& viewport, ClippedPolygon& result,
                  const UserClipPlanes& user) {
  const ClipVertex* bufferA[kMaxClippedVertices + 1];
  const ClipVertex* bufferB[kMaxClippedVertices + 1];
  const ClipVertex** in = bufferA;
  const ClipVertex** out = bufferB;
  in[0] = &v0;
  in[1] = &v1;
  in[2] = &v2;
  int n = 3;
  result.createdCount = 0;

  while (planes != 0 && n >= 3) {
    const int plane = __builtin_ctz(planes);
    planes &= planes - 1;
    const ClipVertex* prev = in[0];
    float dpPrev = distanceToPlane(plane, prev->clip, user);
    if (isInfOrNan(dpPrev)) return false;
    if (n >= kMaxClippedVertices) return false;
    in[n] = in[0];  // close the loop without rotating the vertices
    int outCount = 0;
    for (int i = 1; i <= n; ++i) {
      const ClipVertex* v = in[i];
      const float dp = distanceToPlane(plane, v->clip, user);
      if (isInfOrNan(dp)) return false;
      bool crosses;
      if (dpPrev >= 0.0f) {
        if (outCount >= kMaxClippedVertices) return false;
        out[outCount++] = prev;
        crosses = dp < 0.0f;
      } else {
        crosses = !(dp < 0.0f);
      }
      if (crosses) {
        if (result.createdCount >= kMaxClippedVertices + 1 || outCount >= kMaxClippedVertices) return false;
        ClipVertex& created = result.created[result.createdCount++];
        out[outCount++] = &created;
        const float denom = dp - dpPrev;
        // Interpolate from the end nearer the plane.
        if (dp < 0.0f) {  // leaving
          if (-dp < dpPrev)
            interpolateClipVertex(*v, *prev, dp / denom, attribCount, viewport, created);
          else
            interpolateClipVertex(*prev, *v, -dpPrev / denom, attribCount, viewport, created);
        } else {  // entering
          if (-dpPrev < dp)
            interpolateClipVertex(*prev, *v, -dpPrev / denom, attribCount, viewport, created);
          else
            interpolateClipVertex(*v, *prev, dp / denom, attribCount, viewport, created);
        }
      }
      prev = v;
      dpPrev = dp;
    }
    const ClipVertex** swap = in;
    in = out;
    out = swap;
    n = outCount;
  }
  if (n < 3) return false;
  result.count = n;
  for (int i = 0; i < n; ++i) result.vertex[i] = in[i];
  return true;
}

}  // namespace glfixed::primitive
