#include "raster/pixel_rect.h"

#include <algorithm>
#include <cmath>

namespace glfixed::raster {

namespace {

// st_draw_quad's vertex: clip x = x / width * 2 - 1 (draw_bitmap_quad),
// then the viewport of the whole buffer, upside down for a window-system
// buffer (cso_set_viewport_dims with Y_0_TOP), not for a framebuffer object,
// applied as the vertex shader's epilogue does: fma(clip, scale, translate)
// with w = 1.
WindowVertex quadVertex(float x, float y, float z, float fbWidth, float fbHeight, bool flipY) {
  WindowVertex v;
  const float cx = x / fbWidth * 2.0f - 1.0f;
  const float cy = y / fbHeight * 2.0f - 1.0f;
  const float cz = z * 2.0f - 1.0f;
  v.x = std::fma(cx, fbWidth * 0.5f, fbWidth * 0.5f);
  v.y = std::fma(cy, flipY ? -fbHeight * 0.5f : fbHeight * 0.5f, fbHeight * 0.5f);
  v.z = std::fma(cz, 0.5f, 0.5f);
  v.oneOverW = 1.0f;
  return v;
}

}  // namespace

void drawPixelQuad(const RasterState& state, Framebuffer& fb, const PixelQuad& q) {
  const float w = static_cast<float>(fb.width()), h = static_cast<float>(fb.height());
  const bool flip = !fb.rowsUp();
  WindowVertex v[4] = {quadVertex(q.x0, q.y1, q.z, w, h, flip), quadVertex(q.x1, q.y1, q.z, w, h, flip),
                       quadVertex(q.x1, q.y0, q.z, w, h, flip), quadVertex(q.x0, q.y0, q.z, w, h, flip)};
  const float s[4] = {q.s0, q.s1, q.s1, q.s0}, t[4] = {q.t0, q.t0, q.t1, q.t1};
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 4; ++k) v[i].varying[k] = q.color[k];
    if (state.varyingCount == 8)
      for (int k = 0; k < 4; ++k) v[i].varying[4 + k] = q.secondary[k];
    if (q.texCoords) {
      v[i].varying[kTexCoordVarying + 0] = s[i];
      v[i].varying[kTexCoordVarying + 1] = t[i];
      v[i].varying[kTexCoordVarying + 2] = 0.0f;
      v[i].varying[kTexCoordVarying + 3] = 1.0f;
    }
  }
  float flat[kMaxVaryings] = {};
  for (int k = 0; k < 4; ++k) flat[k] = q.color[k];
  for (int k = 0; k < 4; ++k) flat[4 + k] = q.secondary[k];
  drawTriangle(state, fb, v[0], v[1], v[2], flat);
  drawTriangle(state, fb, v[0], v[2], v[3], flat);
}

void drawPixelRun(const RasterState& state, Framebuffer& fb, int x0, int y0, int x1, int y1, float z,
                  const float color[4], const float secondary[4], const QuadTexCoords* coords) {
  x0 = std::max(x0, state.scissorX0);
  y0 = std::max(y0, state.scissorY0);
  x1 = std::min(x1, state.scissorX1);
  y1 = std::min(y1, state.scissorY1);
  if (x0 >= x1 || y0 >= y1) return;
  PixelQuad q;
  q.x0 = static_cast<float>(x0);
  q.y0 = static_cast<float>(y0);
  q.x1 = static_cast<float>(x1);
  q.y1 = static_cast<float>(y1);
  q.z = z;
  for (int k = 0; k < 4; ++k) q.color[k] = color[k];
  for (int k = 0; k < 4; ++k) q.secondary[k] = secondary[k];
  if (coords) {  // s0, t0 at (x0, y1); s1, t1 at (x1, y0)
    q.texCoords = true;
    q.s0 = (q.x0 - coords->x) / coords->width;
    q.s1 = (q.x1 - coords->x) / coords->width;
    q.t0 = (q.y1 - coords->y) / coords->height;
    q.t1 = (q.y0 - coords->y) / coords->height;
  }
  drawPixelQuad(state, fb, q);
}

}  // namespace glfixed::raster
