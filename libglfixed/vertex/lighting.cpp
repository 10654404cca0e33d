// The lighting stage: GL 2.1 §2.14.1 for a whole batch, evaluated as llvmpipe
// evaluates Mesa 22.3's fixed-function vertex program (ffvertex_prog.c turned
// into NIR; ST_DEBUG=nir prints it): the same operations in the same order, in
// single precision, so that the 8-bit colours round the same way. Where
// llvmpipe departs from the spec, we follow llvmpipe (REFERENCE.md):
//   - every active shininess 0 ("degenerate LIT"): specular is the full
//     specular colour wherever n.L > 0; but an attenuated or spot light goes
//     through LIT with the exponent n.L, so its specular factor is (n.L)^(n.L);
//   - a shininess of 0 next to a non-zero one (two-sided lighting, or a
//     glMaterial(GL_SHININESS) between glBegin and glEnd): LIT computes
//     pow(max(n.h, 0), 0), and llvmpipe's pow(0, y) is 0, so the specular term
//     vanishes where n.h <= 0;
//   - pow is gallivm's exp2/log2 approximation (lighting_math.h);
//   - directional lights get the spot cone too (one constant factor);
//   - attenuation only for local lights whose (k0, k1, k2) is not (1, 0, 0),
//     as NIR rewrote the program's 1 / dot(k, (1, d, d^2)):
//     1 / ((k2 |VP|^2 + k1 sqrt|VP|^2) + k0 (rsq|VP|^2 sqrt|VP|^2));
//   - a back material that varies per vertex (glMaterial between glBegin and
//     glEnd, or glColorMaterial on the back face with per-vertex colours) has
//     its light products computed for red only (a write mask of X in
//     ffvertex_prog.c); green and blue are the front face's product for the
//     same component when that one varies too, otherwise undefined, which
//     llvmpipe turns into NaN (drawn as 255);
//   - a NaN colour is clamped to 1.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "vertex/light_constants.h"
#include "vertex/lighting_math.h"
#include "vertex/vertex_stage.h"
#include "pipeline/thread_scratch.h"

namespace glfixed::vertex {

namespace {

using glm::vec3;
using glm::vec4;

// Light x material products of one face (prog_statevars.c: STATE_LIGHTPROD,
// STATE_LIGHTMODEL_SCENECOLOR), and the face's shininess.
struct FaceProducts {
  vec3 scene{0};    // emission + ambient * light model ambient
  float alpha = 1;  // the diffuse alpha
  float shininess = 0;
  std::array<vec3, kMaxLights> ambient, diffuse, specular;
};
using Products = std::array<FaceProducts, 2>;

inline vec3 mul(const vec3& a, const vec3& b) { return vec3(a.x * b.x, a.y * b.y, a.z * b.z); }
// MAD: a * b + c, a multiply then an add (llvmpipe lowers ffma).
inline vec3 mad(float a, const vec3& b, const vec3& c) {
  return vec3(a * b.x + c.x, a * b.y + c.y, a * b.z + c.z);
}
inline vec3 mad(const vec3& a, const vec3& b, const vec3& c) {
  return vec3(a.x * b.x + c.x, a.y * b.y + c.y, a.z * b.z + c.z);
}
inline vec3 add(const vec3& a, const vec3& b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3 scale(const vec3& v, float s) { return vec3(v.x * s, v.y * s, v.z * s); }

// The material a face is lit with at one vertex: the snapshot's, with the
// components glColorMaterial tracks replaced by the vertex colour.
Material effectiveMaterial(const Material& m, uint32_t tracked, const vec4& color) {
  Material e = m;
  if (tracked & kTrackEmission) e.emission = color;
  if (tracked & kTrackAmbient) e.ambient = color;
  if (tracked & kTrackDiffuse) e.diffuse = color;
  if (tracked & kTrackSpecular) e.specular = color;
  return e;
}

void computeProducts(const LightingConstants& k, const Material& m, FaceProducts& p) {
  p.scene = mad(vec3(k.modelAmbient), vec3(m.ambient), vec3(m.emission));
  p.alpha = m.diffuse.a;
  p.shininess = m.shininess;
  for (int l = 0; l < k.lightCount; ++l) {
    const LightConstants& lc = k.lights[l];
    p.ambient[l] = mul(lc.ambient, vec3(m.ambient));
    p.diffuse[l] = mul(lc.diffuse, vec3(m.diffuse));
    p.specular[l] = mul(lc.specular, vec3(m.specular));
  }
}

// Mesa 22.3's back-face products for per-vertex back materials: the program
// multiplies red only, into a temporary it does not clear. Temporaries are
// handed out lowest first and the front face's products (per-vertex ones only,
// in the order ambient, diffuse, specular) were just released, so the back's
// k-th per-vertex product keeps green and blue of the front's k-th. Without a
// k-th front one the register is undefined: llvmpipe draws garbage there (255
// with one light, arbitrary values with more); we use NaN, drawn as 255.
void applyBackProductQuirk(const LightingConstants& k, uint32_t varying, const FaceProducts& front,
                           FaceProducts& back) {
  using Column = std::array<vec3, kMaxLights>;
  const uint32_t bits[3] = {kTrackAmbient, kTrackDiffuse, kTrackSpecular};
  const Column* frontColumns[3] = {&front.ambient, &front.diffuse, &front.specular};
  Column* backColumns[3] = {&back.ambient, &back.diffuse, &back.specular};
  const Column* frontVarying[3];
  int frontCount = 0;
  for (int j = 0; j < 3; ++j)
    if (varying & bits[j]) frontVarying[frontCount++] = frontColumns[j];
  int backCount = 0;
  for (int j = 0; j < 3; ++j) {
    if (!(varying & (bits[j] << kTrackBackShift))) continue;
    const Column* source = backCount < frontCount ? frontVarying[backCount] : nullptr;
    ++backCount;
    Column& b = *backColumns[j];
    for (int l = 0; l < k.lightCount; ++l) {
      const float nan = std::numeric_limits<float>::quiet_NaN();
      b[l] = source ? vec3(b[l].x, (*source)[l].y, (*source)[l].z) : vec3(b[l].x, nan, nan);
    }
  }
}

// The LIT instruction: (1, max(x, 0), x > 0 ? pow(max(y, 0), clamp(w, +-128)) : 0, 1).
struct Lit {
  float diffuse, specular;
};
inline Lit lit(float nDotL, float nDotH, float exponent) {
  const float w = std::max(std::min(exponent, 128.0f), -128.0f);
  const float power = lp::pow(std::max(nDotH, 0.0f), w);
  return Lit{std::max(nDotL, 0.0f), (0.0f >= nDotL) ? 0.0f : power};
}
// With every shininess 0: (_, max(d, 0), d > 0 ? 1 : 0, _).
inline Lit degenerateLit(float d) { return Lit{std::max(d, 0.0f), (0.0f < d) ? 1.0f : 0.0f}; }

// The space-dependent constants, cached per thread for the last
// (constants generation, modelview) seen.
const LightingSpace& lightingSpace(const LightingConstants& k, const glm::mat4& modelview) {
  struct Cache {
    uint64_t generation = 0;
    glm::mat4 modelview{0};
    LightingSpace space;
  };
  struct SiteCache {};
  Cache& cache = pipeline::threadScratch<Cache, SiteCache>();
  if (cache.generation != k.generation || cache.modelview != modelview) {
    buildLightingSpace(k, modelview, cache.space);
    cache.generation = k.generation;
    cache.modelview = modelview;
  }
  return cache.space;
}

}  // namespace

void lightBatch(const VertexState& state, const VertexBatch& batch, ShadedVertices& out) {
  const LightingConstants& k = *state.lightingConstants;
  const LightingSpace& space = lightingSpace(k, state.eyeFromObject);
  const size_t n = batch.size();
  const bool twoSide = k.twoSide;
  const bool separate = k.separateSpecular;
  out.hasBack = twoSide;
  out.hasSecondary = separate;
  out.primary[kFront].resize(n);
  if (twoSide) out.primary[kBack].resize(n);
  if (separate) {
    out.secondary[kFront].resize(n);
    if (twoSide) out.secondary[kBack].resize(n);
  }
  if (n == 0) return;

  static const MaterialPair kDefaultMaterials{};
  const size_t snapshots = batch.materials.size();
  const MaterialPair& first = snapshots ? batch.materials[0] : kDefaultMaterials;

  // Which material components are per-vertex inputs of Mesa's program: those
  // glMaterial set between glBegin and glEnd, and those glColorMaterial ties
  // to a colour that changes within the batch.
  uint32_t varying = (snapshots > 1 && state.lightingAttrib) ? state.lightingAttrib->beginEndMaterialMask : 0;
  const uint32_t tracked = k.colorMaterial;
  if (tracked) {
    bool colorVaries = false;
    for (size_t i = 1; i < n && !colorVaries; ++i) colorVaries = batch.color[i] != batch.color[0];
    if (colorVaries) varying |= tracked;
  }
  const uint32_t trackedFront = tracked & kFaceMaterialBits;
  const uint32_t trackedBack = (tracked >> kTrackBackShift) & kFaceMaterialBits;
  const bool backQuirk =
      twoSide && (varying >> kTrackBackShift) & (kTrackAmbient | kTrackDiffuse | kTrackSpecular);

  // Mesa's state key: is any active shininess non-zero, or per vertex?
  const bool shininessZero =
      !(first[kFront].shininess != 0.0f || (varying & kMaterialShininess) ||
        (twoSide && (first[kBack].shininess != 0.0f || (varying & (kMaterialShininess << kTrackBackShift)))));

  // Light x material products, once per material snapshot (per vertex for the
  // components that follow the vertex colour).
  struct SiteProducts {};
  std::vector<Products>& products = pipeline::threadScratch<std::vector<Products>, SiteProducts>();
  products.resize(std::max<size_t>(snapshots, 1));
  for (size_t s = 0; s < products.size(); ++s) {
    const MaterialPair& m = snapshots ? batch.materials[s] : kDefaultMaterials;
    computeProducts(k, m[kFront], products[s][kFront]);
    if (twoSide) {
      computeProducts(k, m[kBack], products[s][kBack]);
      if (backQuirk && !tracked) applyBackProductQuirk(k, varying, products[s][kFront], products[s][kBack]);
    }
  }
  Products vertexProducts;

  bool needEyePosition = k.localViewer;
  for (int l = 0; l < k.lightCount; ++l) needEyePosition |= k.lights[l].positional;
  const glm::mat4& mv = state.eyeFromObject;

  for (size_t i = 0; i < n; ++i) {
    const size_t s =
        i < batch.materialIndex.size() ? std::min<size_t>(batch.materialIndex[i], products.size() - 1) : 0;
    const Products* prod = &products[s];
    if (tracked) {
      const MaterialPair& m = snapshots ? batch.materials[s] : kDefaultMaterials;
      const vec4& c = batch.color[i];
      computeProducts(k, effectiveMaterial(m[kFront], trackedFront, c), vertexProducts[kFront]);
      if (twoSide) {
        computeProducts(k, effectiveMaterial(m[kBack], trackedBack, c), vertexProducts[kBack]);
        if (backQuirk) applyBackProductQuirk(k, varying, vertexProducts[kFront], vertexProducts[kBack]);
      }
      prod = &vertexProducts;
    }
    const FaceProducts& front = (*prod)[kFront];
    const FaceProducts& back = (*prod)[kBack];

    // The normal (GL 2.1 §2.11.3), in the lighting space.
    vec3 normal = batch.normal[i];
    if (!space.objectSpace) {
      const vec3 o = normal;
      normal = vec3(lp::dot3(o, space.normalFromObject[0]), lp::dot3(o, space.normalFromObject[1]),
                    lp::dot3(o, space.normalFromObject[2]));
    }
    if (k.normalize)
      normal = lp::normalizeLikeShader(normal);
    else if (!space.objectSpace && k.rescaleNormal)
      normal = scale(normal, space.normalRescale);

    // The eye position, column by column: ((x c0 + y c1) + z c2) + w c3.
    vec3 eye(0), eyeHat(0);
    if (needEyePosition) {
      const vec4& p = batch.position[i];
      eye = ((vec3(mv[0]) * p.x + vec3(mv[1]) * p.y) + vec3(mv[2]) * p.z) + vec3(mv[3]) * p.w;
      if (k.localViewer && !shininessZero) eyeHat = lp::normalizeLikeShader(eye);
    }

    vec3 col0 = front.scene, col1(0);
    vec3 bcol0 = twoSide ? back.scene : vec3(0), bcol1(0);
    for (int l = 0; l < k.lightCount; ++l) {
      const LightConstants& lc = k.lights[l];
      vec3 vp;
      float vpLengthSquared = 0, vpRsq = 0;
      if (lc.positional) {
        vp = lc.position - eye;
        vpLengthSquared = lp::dot3(vp, vp);
        vpRsq = lp::rsq(vpLengthSquared);
        vp = scale(vp, vpRsq);
      } else {
        vp = space.lights[l].direction;
      }

      // Attenuation: the spot factor, then the distance factor.
      bool attenuated = false;
      float att = 1.0f;
      if (lc.spot) {
        attenuated = true;
        if (lc.positional) {
          const float spotDot = lp::dot3(-vp, lc.spotDirection);
          att = (lc.spotCosCutoff < spotDot ? 1.0f : 0.0f) * lp::pow(std::fabs(spotDot), lc.spotExponent);
        } else {
          att = lc.directionalSpotFactor;
        }
      }
      if (lc.attenuated && lc.positional) {
        const float d = std::sqrt(vpLengthSquared);
        const float den =
            (lc.attenuation.z * vpLengthSquared + lc.attenuation.y * d) + lc.attenuation.x * (vpRsq * d);
        const float distanceFactor = lp::rcp(den);
        att = attenuated ? distanceFactor * att : distanceFactor;
        attenuated = true;
      }

      vec3 half(0);
      if (!shininessZero) {
        if (k.localViewer)
          half = lp::normalizeLikeShader(vp - eyeHat);
        else if (!lc.positional)
          half = space.lights[l].halfVector;
        else
          half = lp::normalizeLikeShader(vec3(vp.x, vp.y, vp.z + 1.0f));
      }
      const float nDotL = lp::dot3(normal, vp);
      const float nDotH = shininessZero ? nDotL : lp::dot3(normal, half);

      // One face: LIT, then ambient, diffuse and specular accumulate.
      auto shade = [&](float dl, float dh, float exponent, const FaceProducts& fp, vec3& c0, vec3& c1) {
        Lit t;
        if (attenuated) {
          t = lit(dl, dh, exponent);
          t = Lit{t.diffuse * att, t.specular * att};
          c0 = mad(att, fp.ambient[l], c0);
        } else {
          t = shininessZero ? degenerateLit(dl) : lit(dl, dh, exponent);
          c0 = add(fp.ambient[l], c0);
        }
        c0 = mad(t.diffuse, fp.diffuse[l], c0);
        if (separate)
          c1 = mad(t.specular, fp.specular[l], c1);
        else
          c0 = mad(t.specular, fp.specular[l], c0);
      };
      // With every shininess 0 the exponent slot holds n.L too.
      shade(nDotL, nDotH, shininessZero ? nDotL : front.shininess, front, col0, col1);
      if (twoSide) shade(-nDotL, -nDotH, shininessZero ? -nDotL : back.shininess, back, bcol0, bcol1);
    }

    out.primary[kFront][i] = lp::clampColor(vec4(col0, front.alpha));
    if (separate) out.secondary[kFront][i] = lp::clampColor(vec4(col1, 0.0f));
    if (twoSide) {
      out.primary[kBack][i] = lp::clampColor(vec4(bcol0, back.alpha));
      if (separate) out.secondary[kBack][i] = lp::clampColor(vec4(bcol1, 0.0f));
    }
  }
}

}  // namespace glfixed::vertex
