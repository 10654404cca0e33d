// Texture coordinates per vertex (vertex/texcoord.h). Every operation is one
// of the shader's, rounded as llvmpipe rounds it: no fused multiply-adds.
#pragma GCC optimize("fp-contract=off")

#include "vertex/texcoord.h"

#include "state/context.h"
#include "vertex/lighting_math.h"
#include "vertex/lighting_matrix.h"

namespace glfixed::vertex {

namespace {

using glm::vec3;
using glm::vec4;

// The shader's DP4: summed from w down, unfused.
inline float dot4(const vec4& a, const vec4& b) { return ((a.w * b.w + a.z * b.z) + a.y * b.y) + a.x * b.x; }

// m * v as a multiply and three multiply-adds down the columns.
inline vec4 transformColumns(const glm::mat4& m, const vec4& v) {
  vec4 r = m[0] * v.x;
  r = m[1] * v.y + r;
  r = m[2] * v.z + r;
  return m[3] * v.w + r;
}

bool isIdentity(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (m[c][r] != (c == r ? 1.0f : 0.0f)) return false;
  return true;
}

// What one vertex needs from the others' shared values (the shader computes
// each once per vertex and reuses it).
struct Shared {
  bool eyeDone = false, normalDone = false, eyeHatDone = false;
  vec4 eye{0};
  vec3 normal{0}, eyeHat{0};
};

struct VertexInputs {
  const glm::mat4& eyeFromObject;
  const vec4& position;
  const vec3& normal;
};

const vec4& eyeOf(const VertexInputs& in, Shared& s) {
  if (!s.eyeDone) {
    s.eye = transformColumns(in.eyeFromObject, in.position);
    s.eyeDone = true;
  }
  return s.eye;
}

const vec3& normalOf(const TexCoordState& st, const VertexInputs& in, Shared& s) {
  if (!s.normalDone) {
    // get_transformed_normal with eye coordinates: the rows of the inverse
    // transpose, then GL_NORMALIZE or GL_RESCALE_NORMAL.
    const vec3& o = in.normal;
    vec3 n(lp::dot3(o, st.normalFromObject[0]), lp::dot3(o, st.normalFromObject[1]),
           lp::dot3(o, st.normalFromObject[2]));
    if (st.normalize)
      n = lp::normalizeLikeShader(n);
    else if (st.rescale)
      n = vec3(n.x * st.normalRescale, n.y * st.normalRescale, n.z * st.normalRescale);
    s.normal = n;
    s.normalDone = true;
  }
  return s.normal;
}

const vec3& eyeHatOf(const VertexInputs& in, Shared& s) {
  if (!s.eyeHatDone) {
    s.eyeHat = lp::normalizeLikeShader(vec3(eyeOf(in, s)));
    s.eyeHatDone = true;
  }
  return s.eyeHat;
}

// The reflection vector (build_reflect_texgen): u - 2 (n.u) n.
vec3 reflection(const TexCoordState& st, const VertexInputs& in, Shared& s) {
  const vec3& n = normalOf(st, in, s);
  const vec3& u = eyeHatOf(in, s);
  float d = lp::dot3(n, u);
  d = d + d;
  return vec3(-d * n.x + u.x, -d * n.y + u.y, -d * n.z + u.z);
}

// The sphere map (build_sphere_texgen): r / m + 1/2 with
// 1/m = rsq(rx^2 + ry^2 + (rz + 1)^2) * 0.5.
vec3 sphere(const TexCoordState& st, const VertexInputs& in, Shared& s) {
  const vec3 r = reflection(st, in, s);
  const vec3 t(r.x + 0.0f, r.y + 0.0f, r.z + 1.0f);
  const float invM = lp::rsq(lp::dot3(t, t)) * 0.5f;
  return vec3(r.x * invM + 0.5f, r.y * invM + 0.5f, r.z * invM + 0.5f);
}

vec4 unitCoords(const TexCoordState& st, const TexCoordUnit& unit, const VertexInputs& in, const vec4& given,
                Shared& s) {
  vec4 t = given;
  if (unit.texgen) {
    bool sphereDone = false, reflectDone = false;
    vec3 sp(0), rf(0);
    for (int j = 0; j < 4; ++j) {
      switch (unit.gen[j]) {
        case GL_OBJECT_LINEAR: t[j] = dot4(in.position, unit.objectPlane[j]); break;
        case GL_EYE_LINEAR: t[j] = dot4(eyeOf(in, s), unit.eyePlane[j]); break;
        case GL_SPHERE_MAP:
          if (!sphereDone) sp = sphere(st, in, s), sphereDone = true;
          t[j] = sp[j];
          break;
        case GL_REFLECTION_MAP:
          if (!reflectDone) rf = reflection(st, in, s), reflectDone = true;
          t[j] = rf[j];
          break;
        case GL_NORMAL_MAP: t[j] = normalOf(st, in, s)[j]; break;
        default: break;  // not generated: the given coordinate
      }
    }
  }
  return unit.matrix ? transformColumns(unit.textureMatrix, t) : t;
}

}  // namespace

bool textureUnitEnabled(const Context& ctx, int u) {
  const TextureUnitEnables& e = ctx.texture.enables[u];
  return e.texture1D || e.texture2D || e.texture3D || e.textureCubeMap;
}

uint32_t texCoordInputUnits(const Context& ctx) {
  uint32_t units = ctx.renderMode.mode == GL_FEEDBACK ? 1u : 0u;
  for (int u = 0; u < kMaxTextureUnits; ++u)
    if (textureUnitEnabled(ctx, u)) units |= 1u << u;
  return units;
}

void buildTexCoordState(const Context& ctx, TexCoordState& out) {
  out.units = 0;
  out.needEyeCoords = false;
  out.needNormal = false;
  const bool feedback = ctx.renderMode.mode == GL_FEEDBACK;
  for (int u = 0; u < kMaxTextureUnits; ++u) {
    const bool enabled = textureUnitEnabled(ctx, u);
    if (!enabled && !(feedback && u == 0)) continue;
    out.units |= 1u << u;
    TexCoordUnit& unit = out.unit[u];
    unit.current = ctx.current.texCoord[u];
    // Mesa computes texgen and the texture matrix only for units whose
    // texture is enabled (_TexGenEnabled, _TexMatEnabled); unit 0 forced out
    // by GL_FEEDBACK alone passes the coordinates through.
    unit.texgen = false;
    unit.matrix = false;
    if (!enabled) continue;
    const TextureUnitEnables& e = ctx.texture.enables[u];
    const bool genOn[4] = {e.genS, e.genT, e.genR, e.genQ};
    const TexGenAttrib& g = ctx.texture.texgen[u];
    for (int j = 0; j < 4; ++j) {
      unit.gen[j] = genOn[j] ? g.coord[j].mode : 0;
      unit.objectPlane[j] = g.coord[j].objectPlane;
      unit.eyePlane[j] = g.coord[j].eyePlane;
      if (!genOn[j]) continue;
      unit.texgen = true;
      if (g.coord[j].mode != GL_OBJECT_LINEAR) out.needEyeCoords = true;
      if (g.coord[j].mode != GL_OBJECT_LINEAR && g.coord[j].mode != GL_EYE_LINEAR) out.needNormal = true;
    }
    const glm::mat4& m = ctx.textureMatrix[u].top();
    unit.matrix = !isIdentity(m);
    unit.textureMatrix = m;
  }
  if (out.needNormal) {
    const ModelviewAnalysis mv = analyseModelview(ctx.modelview.top());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.normalFromObject[i][j] = mv.inverse[i][j];
    out.normalize = ctx.transform.normalize;
    out.rescale = !out.normalize && ctx.transform.rescaleNormal;
    out.normalRescale = mv.normalRescale;
  }
}

glm::vec4 texCoordOfVertex(const TexCoordState& state, int u, const glm::mat4& eyeFromObject,
                           const glm::vec4& position, const glm::vec3& normal, const glm::vec4& texCoord) {
  Shared s;
  const VertexInputs in{eyeFromObject, position, normal};
  return unitCoords(state, state.unit[u], in, texCoord, s);
}

void computeTexCoords(const TexCoordState& state, const glm::mat4& eyeFromObject, const VertexBatch& batch,
                      ShadedVertices& out) {
  out.texCoordUnits = state.units;
  const size_t n = batch.size();
  for (uint32_t m = state.units; m != 0; m &= m - 1) out.texCoord[__builtin_ctz(m)].resize(n);
  for (size_t i = 0; i < n; ++i) {
    Shared s;
    const VertexInputs in{eyeFromObject, batch.position[i], batch.normal[i]};
    for (uint32_t m = state.units; m != 0; m &= m - 1) {
      const int u = __builtin_ctz(m);
      const vec4& given = (batch.texCoordUnits >> u & 1u) ? batch.texCoord[u][i] : state.unit[u].current;
      out.texCoord[u][i] = unitCoords(state, state.unit[u], in, given, s);
    }
  }
}

}  // namespace glfixed::vertex
