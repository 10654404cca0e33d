#include "pipeline/array_fetch.h"

#include <algorithm>
#include <cstring>
#include <type_traits>

#include "state/context.h"
#include "vertex/texcoord.h"

namespace glfixed::pipeline {

namespace {

// Table 2.9, as llvmpipe's vertex fetch evaluates it (unorm: c / (2^b - 1);
// snorm: c / (2^(b-1) - 1) clamped to -1; a multiply by the reciprocal).
template <typename T>
float convert(const uint8_t* p, bool normalized) {
  T c;
  std::memcpy(&c, p, sizeof(T));
  if constexpr (std::is_floating_point_v<T>) {
    return static_cast<float>(c);
  } else {
    const float f = static_cast<float>(c);
    if (!normalized) return f;
    if constexpr (std::is_signed_v<T>) {
      constexpr double maxValue = double((uint64_t(1) << (8 * sizeof(T) - 1)) - 1);
      return std::max(f * static_cast<float>(1.0 / maxValue), -1.0f);
    } else {
      constexpr double maxValue = double((uint64_t(1) << (8 * sizeof(T))) - 1);
      // gallivm's unorm to float for up to 16 bits (lp_build_unsigned_norm_to_float):
      // c / 2^b, exact, times 2^b / (2^b - 1) rounded to float.
      if constexpr (sizeof(T) <= 2) {
        constexpr double range = double(uint64_t(1) << (8 * sizeof(T)));
        return (f * static_cast<float>(1.0 / range)) * static_cast<float>(range / maxValue);
      }
      return f * static_cast<float>(1.0 / maxValue);
    }
  }
}

float component(GLenum type, const uint8_t* p, bool normalized) {
  switch (type) {
    case GL_BYTE: return convert<int8_t>(p, normalized);
    case GL_UNSIGNED_BYTE: return convert<uint8_t>(p, normalized);
    case GL_SHORT: return convert<int16_t>(p, normalized);
    case GL_UNSIGNED_SHORT: return convert<uint16_t>(p, normalized);
    case GL_INT: return convert<int32_t>(p, normalized);
    case GL_UNSIGNED_INT: return convert<uint32_t>(p, normalized);
    case GL_FLOAT: return convert<float>(p, normalized);
    case GL_DOUBLE: return convert<double>(p, normalized);
    default: return 0;
  }
}

// false: the array sources a mapped buffer.
bool resolve(const Context& ctx, const ClientArray& a, bool normalized, ArrayView& v) {
  v.size = componentCount(a);
  v.bgra = a.size == GL_BGRA;
  v.type = a.type;
  v.normalized = normalized;
  v.stride = effectiveStride(a);
  const uintptr_t offset = reinterpret_cast<uintptr_t>(a.pointer);
  if (a.orphaned) {  // an offset into a deleted buffer: zeros
    v.base = nullptr;
    v.limit = 0;
    return true;
  }
  if (a.bufferBinding == 0) {
    v.base = static_cast<const uint8_t*>(a.pointer);
    v.limit = v.base ? SIZE_MAX : 0;  // a null client pointer reads as zeros
    return true;
  }
  const BufferObject* b = ctx.buffers.find(a.bufferBinding);
  if (!b) {
    v.base = nullptr;
    v.limit = 0;
    return true;
  }
  if (b->mapped) return false;
  const size_t size = b->data.size();
  v.base = b->data.data() + std::min<size_t>(offset, size);
  v.limit = offset >= size ? 0 : size - offset;
  return true;
}

template <typename Each>
void appendEach(const ArraySources& src, const Context& ctx, size_t count, VertexBatch& batch, Each indexAt) {
  const size_t start = batch.size();
  if (start == 0) batch.setTexCoordUnits(vertex::texCoordInputUnits(ctx));  // texture coordinates (issue 14)
  if (start == 0) batch.setHasFogCoord(vertex::fogCoordInput(ctx));         // fog
  if (start == 0) batch.setHasSecondaryColor(!ctx.lighting.lighting && ctx.fog.colorSum);  // the colour sum
  batch.resizeVertices(start + count);
  const glm::vec4 currentNormal(ctx.current.normal, 0.0f);
  const glm::vec4& currentColor = ctx.current.color;
  for (size_t k = 0; k < count; ++k) {
    const uint32_t i = indexAt(k);
    const size_t o = start + k;
    batch.position[o] = src.vertexView.read(i, glm::vec4(0, 0, 0, 1));
    batch.normal[o] = src.normal ? glm::vec3(src.normalView.read(i, currentNormal)) : ctx.current.normal;
    batch.color[o] = src.color ? src.colorView.read(i, glm::vec4(0, 0, 0, 1)) : currentColor;
    batch.materialIndex[o] = 0;
    // Polygon area: the edge flag array, else the current edge flag.
    batch.edgeFlag[o] =
        src.edgeFlag ? src.edgeFlagView.read(i, glm::vec4(1)).x != 0.0f : ctx.current.edgeFlag;
    // Texture coordinates (issue 14): the unit's array, else its current coordinates.
    for (uint32_t m = batch.texCoordUnits; m != 0; m &= m - 1) {
      const int u = __builtin_ctz(m);
      batch.texCoord[u][o] = src.texCoord[u] ? src.texCoordView[u].read(i, glm::vec4(0, 0, 0, 1))
                                             : ctx.current.texCoord[u];
    }
    // Fog: the fog coordinate array, else the current fog coordinate.
    if (batch.hasFogCoord)
      batch.fogCoord[o] = src.fogCoord ? src.fogCoordView.read(i, glm::vec4(0)).x : ctx.current.fogCoord;
    if (batch.hasSecondaryColor)
      batch.secondaryColor[o] =
          src.secondaryColor ? src.secondaryColorView.read(i, glm::vec4(0, 0, 0, 1)) : ctx.current.secondaryColor;
  }
}

}  // namespace

const uint8_t* ArrayView::elementBytes(uint32_t i) const {
  const size_t at = static_cast<size_t>(i) * stride;
  const size_t need = static_cast<size_t>(size) * componentBytes(type);
  if (base == nullptr || (limit != SIZE_MAX && (at > limit || limit - at < need))) return nullptr;
  return base + at;
}

glm::vec4 ArrayView::read(uint32_t i, glm::vec4 fill) const {
  const int bytes = componentBytes(type);
  const uint8_t* p = elementBytes(i);
  // Past the end of a buffer object (or a null pointer): zeros.
  if (!p) {
    for (int c = 0; c < size && c < 4; ++c) fill[c] = 0;
    return fill;
  }
  for (int c = 0; c < size && c < 4; ++c) fill[c] = component(type, p + c * bytes, normalized);
  if (bgra) std::swap(fill[0], fill[2]);
  return fill;
}

GLenum resolveArrays(const Context& ctx, ArraySources& out) {
  const VertexArrayAttrib& a = ctx.vertexArray;
  out = ArraySources();
  out.vertex = a.vertex.enabled;
  out.normal = a.normal.enabled;
  out.color = a.color.enabled;
  bool ok = true;
  if (out.vertex) ok &= resolve(ctx, a.vertex, false, out.vertexView);
  if (out.normal) ok &= resolve(ctx, a.normal, true, out.normalView);
  if (out.color) ok &= resolve(ctx, a.color, true, out.colorView);
  // The arrays not fetched may not source a mapped buffer either.
  auto other = [&](const ClientArray& c, bool normalized, bool& enabled, ArrayView& view) {
    enabled = c.enabled;
    if (enabled) ok &= resolve(ctx, c, normalized, view);
  };
  other(a.secondaryColor, true, out.secondaryColor, out.secondaryColorView);
  other(a.fogCoord, false, out.fogCoord, out.fogCoordView);
  other(a.index, false, out.index, out.indexView);
  other(a.edgeFlag, false, out.edgeFlag, out.edgeFlagView);
  for (int u = 0; u < kMaxTextureCoords; ++u)
    other(a.texCoord[u], false, out.texCoord[u], out.texCoordView[u]);
  return ok ? GL_NO_ERROR : GL_INVALID_OPERATION;
}

void appendRange(const ArraySources& src, const Context& ctx, uint32_t first, uint32_t count,
                 VertexBatch& batch) {
  appendEach(src, ctx, count, batch, [first](size_t k) { return first + static_cast<uint32_t>(k); });
}

void appendIndexed(const ArraySources& src, const Context& ctx, const uint32_t* indices, size_t count,
                   VertexBatch& batch) {
  appendEach(src, ctx, count, batch, [indices](size_t k) { return indices[k]; });
}

}  // namespace glfixed::pipeline
