// An independent double-precision model of GL 2.1 §2.14.1 (the lighting
// equation) and §2.11.3 (normal transformation), written from the
// specification's equations, for testing the lighting stage. It shares no code
// with libglfixed/vertex/: its inputs are plain doubles.
//
// The equation, for one face with normal n (eye space), vertex V:
//   c_pri = e_cm + a_cm a_cs
//         + sum_i att_i spot_i [ a_cm a_cli + (n (.) VP_pli) d_cm d_cli
//                                + f_i (n (.) h^_i)^s_rm s_cm s_cli ]
// where (.) is max(dot, 0); VP_pli is the unit vector from V to the light
// (a directional light's own direction when P_pli.w = 0); f_i = 1 iff
// n . VP_pli > 0; h_i = VP_pli + VP_e with VP_e = unit(-V) for a local viewer,
// else (0, 0, 1); att_i = 1 / (k0 + k1 ||VP|| + k2 ||VP||^2) for a local
// light, else 1; spot_i = (-VP_pli . s^)^s_rl inside the cone
// (-VP_pli . s^ >= cos c_rl), 0 outside, 1 for a cutoff of 180 (a directional
// light uses its direction here too). With GL_SEPARATE_SPECULAR_COLOR the
// specular sum goes to c_sec instead. Alpha is d_cm's alpha. The back face
// uses -n and the back material. Colours are clamped to [0, 1].
//
// llvmpipe's documented departures for shininess 0 (REFERENCE.md) are a
// separate, explicit option (ShininessRule), so a test states which one it
// expects.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace oracle {

using glm::dmat3;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;

struct Light {
  dvec4 ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
  dvec4 position{0, 0, 1, 0};     // eye space
  dvec3 spotDirection{0, 0, -1};  // eye space
  double spotExponent = 0, spotCutoff = 180;
  double k0 = 1, k1 = 0, k2 = 0;
};

struct Material {
  dvec4 ambient{0.2, 0.2, 0.2, 1}, diffuse{0.8, 0.8, 0.8, 1}, specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
  double shininess = 0;
};

enum class ShininessRule {
  kSpec,             // x^0 = 1, also for x = 0
  kLlvmpipeAllZero,  // every active shininess 0: f_i for plain lights, (n.L)^(n.L) for attenuated/spot ones
  kLlvmpipeZeroPowZero,  // pow(0, 0) = 0
};

struct Model {
  std::vector<Light> lights;
  dvec4 modelAmbient{0.2, 0.2, 0.2, 1};
  bool localViewer = false;
  bool separateSpecular = false;
  ShininessRule shininessRule = ShininessRule::kSpec;
};

struct FaceColor {
  dvec4 primary{0};
  dvec3 secondary{0};
  double minNDotL = 1e9;       // min |n . VP| over lights: how close f_i is to switching
  double minSpotMargin = 1e9;  // min |-VP . s - cos c| over spot lights
  double minNDotH = 1e9;       // min |n . h^| over lights
  double maxUnclamped = 0;     // the largest colour component before clamping
  double maxPower = 0;         // the largest (n (.) h^)^s, before attenuation
};

inline double clamp01(double v) { return std::min(std::max(v, 0.0), 1.0); }

// GL 2.1 §2.11.3: n_eye = (M^-1)^T n over the upper 3x3; GL_NORMALIZE makes it
// unit length; GL_RESCALE_NORMAL scales by 1/sqrt(m31^2 + m32^2 + m33^2), m the
// entries of the inverse's third row.
inline dvec3 eyeNormal(const dmat4& modelview, const dvec3& n, bool normalize, bool rescale) {
  const dmat3 inv = glm::inverse(dmat3(modelview));
  dvec3 e = glm::transpose(inv) * n;
  if (normalize) {
    e = glm::normalize(e);
  } else if (rescale) {
    const double f = 1.0 / std::sqrt(inv[0][2] * inv[0][2] + inv[1][2] * inv[1][2] + inv[2][2] * inv[2][2]);
    e *= f;
  }
  return e;
}

inline FaceColor lightFace(const Model& m, const Material& mat, const dvec3& V, const dvec3& n) {
  FaceColor out;
  dvec3 c = dvec3(mat.emission) + dvec3(mat.ambient) * dvec3(m.modelAmbient);
  dvec3 sec(0);
  for (const Light& L : m.lights) {
    dvec3 vp;
    double att = 1;
    if (L.position.w != 0) {
      const dvec3 p = dvec3(L.position) / L.position.w;
      const dvec3 d = p - V;
      const double dist = glm::length(d);
      vp = d / dist;
      att = 1.0 / (L.k0 + L.k1 * dist + L.k2 * dist * dist);
    } else {
      vp = glm::normalize(dvec3(L.position));
    }
    double spot = 1;
    const bool isSpot = L.spotCutoff != 180;
    if (isSpot) {
      const double sd = glm::dot(-vp, glm::normalize(L.spotDirection));
      const double cosCut = std::cos(L.spotCutoff * M_PI / 180.0);
      out.minSpotMargin = std::min(out.minSpotMargin, std::fabs(sd - cosCut));
      spot = sd >= cosCut ? std::pow(std::max(sd, 0.0), L.spotExponent) : 0.0;
    }
    const dvec3 ve = m.localViewer ? glm::normalize(-V) : dvec3(0, 0, 1);
    const dvec3 h = glm::normalize(vp + ve);
    const double nl = glm::dot(n, vp);
    const double nh = glm::dot(n, h);
    out.minNDotL = std::min(out.minNDotL, std::fabs(nl));
    out.minNDotH = std::min(out.minNDotH, std::fabs(nh));
    const double f = nl > 0 ? 1.0 : 0.0;
    double specFactor;
    switch (m.shininessRule) {
      case ShininessRule::kSpec: specFactor = f * std::pow(std::max(nh, 0.0), mat.shininess); break;
      case ShininessRule::kLlvmpipeAllZero: {
        // A light with distance attenuation or a spot cone goes through LIT
        // with the exponent n.L; the others get the full specular colour.
        const bool attenuated = (L.position.w != 0 && (L.k0 != 1 || L.k1 != 0 || L.k2 != 0)) || isSpot;
        specFactor = attenuated ? f * std::pow(std::max(nl, 0.0), nl) : f;
        break;
      }
      case ShininessRule::kLlvmpipeZeroPowZero:
      default: specFactor = (nh <= 0) ? 0.0 : f * std::pow(nh, mat.shininess); break;
    }
    out.maxPower = std::max(out.maxPower, std::pow(std::max(nh, 0.0), mat.shininess));
    const double a = att * spot;
    c += a *
         (dvec3(mat.ambient) * dvec3(L.ambient) + std::max(nl, 0.0) * dvec3(mat.diffuse) * dvec3(L.diffuse));
    const dvec3 s = a * specFactor * dvec3(mat.specular) * dvec3(L.specular);
    if (m.separateSpecular)
      sec += s;
    else
      c += s;
  }
  out.maxUnclamped = std::max(
      {std::fabs(c.x), std::fabs(c.y), std::fabs(c.z), std::fabs(sec.x), std::fabs(sec.y), std::fabs(sec.z)});
  out.primary = dvec4(clamp01(c.x), clamp01(c.y), clamp01(c.z), clamp01(mat.diffuse.a));
  out.secondary = dvec3(clamp01(sec.x), clamp01(sec.y), clamp01(sec.z));
  return out;
}

}  // namespace oracle
