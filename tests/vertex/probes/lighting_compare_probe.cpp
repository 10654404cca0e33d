// Compares libglfixed's lighting stage with llvmpipe, case by case: random
// lighting states, each vertex lit by llvmpipe (OSMesa) as the provoking vertex
// of a one-pixel flat-shaded triangle (front- or back-facing), and by
// glfixed::vertex::lightBatch, compared as 8-bit colours. 16384 cases a frame.
//
// Build (from a checkout, with Mesa's libosmesa6-dev installed):
//   L=libglfixed; g++ -O2 -std=c++17 -Iinclude -I$L -o lighting_compare_probe
//     tests/vertex/probes/lighting_compare_probe.cpp $L/vertex/lighting.cpp
//     $L/vertex/light_constants.cpp $L/vertex/lighting_matrix.cpp
//     $L/vertex/lighting_math.cpp -lOSMesa      (one command)
// Run: ./lighting_compare_probe <frames> <seed> <preset>
//   presets: mixed dir dirobj pos spot atten shin0 highshin material colormat many lv
//   environment: VERBOSE=1 (per-frame lines, first mismatches), MVKIND=0..4,
//   TWOSIDE= SEP= LV= SHIN0= SAMEBACK= (probabilities), SUBSET=1 (random subsets
//   of per-vertex material components), UNDEF=1 / CMBACK=1 (allow the states
//   where llvmpipe reads an undefined register: they mismatch by design).
//   WRAND=1 (vertices with w in [0.5, 2]).
// Measured (Mesa 22.3.6, llvmpipe): 0 mismatching pixels over 17.0M cases:
// every preset above and SUBSET=1 material, seeds 11-15, 16 frames each.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <string>
#include <vector>

#include "pipeline/vertex_batch.h"
#include "state/attribs.h"
#include "state/lighting_attrib.h"
#include "vertex/light_constants.h"
#include "vertex/lighting_matrix.h"
#include "vertex/vertex_stage.h"

using namespace glfixed;
using glm::vec3;
using glm::vec4;

static const int W = 128, H = 128;
static double sameBack = 0.5;
static std::mt19937 rng;
static float U(float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); }
static int I(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }
static bool P(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
static vec3 randDir() {
  for (;;) {
    vec3 v(U(-1, 1), U(-1, 1), U(-1, 1));
    float l = glm::length(v);
    if (l > 0.1f && l <= 1) return v / l;
  }
}
static vec4 randColor(float lo = 0, float hi = 1) { return vec4(U(lo, hi), U(lo, hi), U(lo, hi), U(0, 1)); }

struct Options {
  int lightsMax = 3;
  double pPositional = 0.5, pSpot = 0.3, pAtten = 0.3;
  double pLocalViewer = 0.3, pTwoSide = 0.5, pSeparate = 0.3, pNormalize = 0.5, pRescale = 0.3;
  double pShin0 = 0.2, pBeginEndMaterial = 0.0, pColorMaterial = 0.0;
  int mvKind = -1;  // -1 random; 0 identity, 1 rotation, 2 rot+translate, 3 rot+scale, 4 general affine
  double pUnitNormal = 0.5;
  double highShininess = 0.0;  // fraction of materials with shininess in [64,128]
};

glm::mat4 randomModelview(int kind) {
  glm::mat4 m(1.0f);
  switch (kind) {
    case 0: break;
    case 1: m = glm::rotate(glm::mat4(1), U(0, 6.28f), randDir()); break;
    case 2:
      m = glm::translate(glm::mat4(1), vec3(U(-1, 1), U(-1, 1), U(-1, 1))) *
          glm::rotate(glm::mat4(1), U(0, 6.28f), randDir());
      break;
    case 3:
      m = glm::rotate(glm::mat4(1), U(0, 6.28f), randDir()) *
          glm::scale(glm::mat4(1), vec3(U(0.5f, 2), U(0.5f, 2), U(0.5f, 2)));
      break;
    default:
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = U(-1.5f, 1.5f);
      m[3] = vec4(U(-1, 1), U(-1, 1), U(-1, 1), 1);
      {
        glm::mat3 inv = glm::inverse(glm::mat3(m));
        float mx = 0;
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) mx = std::max(mx, std::fabs(inv[c][r]));
        if (!(mx < 3.0f)) m = glm::mat4(1);
      }
  }
  return m;
}

Material randomMaterial(const Options& o) {
  Material m;
  m.ambient = randColor();
  m.diffuse = randColor();
  m.specular = randColor();
  m.emission = P(0.3) ? randColor(0, 0.3f) : vec4(0, 0, 0, 1);
  m.shininess = P(o.pShin0) ? 0.0f : (P(o.highShininess) ? U(64, 128) : U(0, 128));
  return m;
}

int main(int argc, char** argv) {
  int frames = argc > 1 ? atoi(argv[1]) : 4;
  unsigned seed = argc > 2 ? atoi(argv[2]) : 1;
  std::string preset = argc > 3 ? argv[3] : "mixed";
  rng.seed(seed);
  Options o;
  if (preset == "dir") {
    o.pPositional = 0;
    o.pSpot = 0;
    o.pAtten = 0;
    o.pLocalViewer = 0;
    o.pSeparate = 0;
  }
  if (preset == "dirobj") {
    o.pPositional = 0;
    o.pSpot = 0;
    o.pAtten = 0;
    o.pLocalViewer = 0;
    o.pSeparate = 0;
    o.mvKind = 1;
  }
  if (preset == "pos") {
    o.pPositional = 1;
    o.pSpot = 0;
    o.pAtten = 0;
  }
  if (preset == "spot") {
    o.pSpot = 1;
  }
  if (preset == "atten") {
    o.pPositional = 1;
    o.pAtten = 1;
    o.pSpot = 0;
  }
  if (preset == "shin0") {
    o.pShin0 = 1;
  }
  if (preset == "highshin") {
    o.highShininess = 1;
    o.pShin0 = 0;
  }
  if (preset == "material") {
    o.pBeginEndMaterial = 1;
  }
  if (preset == "colormat") {
    o.pColorMaterial = 1;
  }
  if (preset == "many") {
    o.lightsMax = 8;
  }
  if (preset == "lv") {
    o.pLocalViewer = 1;
  }
  if (const char* e = getenv("MVKIND")) o.mvKind = atoi(e);
  if (const char* e = getenv("TWOSIDE")) o.pTwoSide = atof(e);
  if (const char* e = getenv("SEP")) o.pSeparate = atof(e);
  if (const char* e = getenv("LV")) o.pLocalViewer = atof(e);
  if (const char* e = getenv("SHIN0")) o.pShin0 = atof(e);
  if (const char* e = getenv("SAMEBACK")) sameBack = atof(e);
  const bool verbose = getenv("VERBOSE") != nullptr;

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  std::vector<unsigned char> buf(W * H * 4);
  OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, W, H);
  glViewport(0, 0, W, H);
  glShadeModel(GL_FLAT);
  glDisable(GL_DITHER);

  long total = 0, mism = 0, mismChannels = 0, maxDiff = 0;
  for (int frame = 0; frame < frames; ++frame) {
    // ---- state ----
    LightingAttrib la;
    TransformAttrib ta;
    la.lighting = true;
    const int mvKind = o.mvKind >= 0 ? o.mvKind : I(0, 4);
    const glm::mat4 lightMv = randomModelview(I(0, 4));
    const glm::mat4 mv = randomModelview(mvKind);
    la.model.ambient = randColor(0, 0.4f);
    la.model.localViewer = P(o.pLocalViewer);
    la.model.twoSide = P(o.pTwoSide);
    la.model.colorControl = P(o.pSeparate) ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR;
    ta.normalize = P(o.pNormalize);
    ta.rescaleNormal = !ta.normalize && P(o.pRescale);
    const bool beginEndMaterial = P(o.pBeginEndMaterial);
    // Which components glMaterial sets per case: all, or a random subset per face.
    uint32_t subset[2] = {0x1f, 0x1f};
    if (getenv("SUBSET")) {
      for (;;) {
        subset[0] = I(0, 31);
        subset[1] = I(0, 31);
        int fc = __builtin_popcount(subset[0] & 0xe), bc = __builtin_popcount(subset[1] & 0xe);
        if (getenv("UNDEF") || bc <= fc || !la.model.twoSide) break;
      }
    }
    const bool colorMaterial = P(o.pColorMaterial);
    const GLenum cmFaces[3] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
    const GLenum cmModes[5] = {GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE};
    la.colorMaterial = colorMaterial;
    la.colorMaterialFace = cmFaces[I(0, 2)];
    if (la.colorMaterialFace == GL_BACK && la.model.twoSide && !getenv("CMBACK"))
      la.colorMaterialFace = GL_FRONT_AND_BACK;
    la.colorMaterialParameter = cmModes[I(0, 4)];

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(&lightMv[0][0]);
    for (int i = 0; i < 8; ++i) glDisable(GL_LIGHT0 + i);
    const int nl = I(1, o.lightsMax);
    for (int i = 0; i < nl; ++i) {
      const int li = (nl == 8) ? i : I(0, 7);
      Light& L = la.light[li];
      L = Light{};
      L.enabled = true;
      L.ambient = randColor(0, 0.5f);
      L.diffuse = randColor();
      L.specular = randColor();
      vec4 pos = P(o.pPositional) ? vec4(U(-3, 3), U(-3, 3), U(-3, 3), P(0.8) ? 1.0f : U(0.5f, 2))
                                  : vec4(randDir() * U(0.5f, 2), 0);
      if (P(o.pSpot)) {
        L.spotCutoff = P(0.1) ? 90.0f : U(5, 89);
        L.spotExponent = P(0.2) ? 0.0f : U(0, 128);
      }
      vec3 sdir = randDir() * U(0.5f, 2);
      if (P(o.pAtten)) {
        L.constantAttenuation = U(0.2f, 2);
        L.linearAttenuation = P(0.7) ? U(0, 1) : 0;
        L.quadraticAttenuation = P(0.7) ? U(0, 0.5f) : 0;
      }
      glLightfv(GL_LIGHT0 + li, GL_AMBIENT, &L.ambient[0]);
      glLightfv(GL_LIGHT0 + li, GL_DIFFUSE, &L.diffuse[0]);
      glLightfv(GL_LIGHT0 + li, GL_SPECULAR, &L.specular[0]);
      glLightfv(GL_LIGHT0 + li, GL_POSITION, &pos[0]);
      glLightfv(GL_LIGHT0 + li, GL_SPOT_DIRECTION, &sdir[0]);
      glLightf(GL_LIGHT0 + li, GL_SPOT_CUTOFF, L.spotCutoff);
      glLightf(GL_LIGHT0 + li, GL_SPOT_EXPONENT, L.spotExponent);
      glLightf(GL_LIGHT0 + li, GL_CONSTANT_ATTENUATION, L.constantAttenuation);
      glLightf(GL_LIGHT0 + li, GL_LINEAR_ATTENUATION, L.linearAttenuation);
      glLightf(GL_LIGHT0 + li, GL_QUADRATIC_ATTENUATION, L.quadraticAttenuation);
      glEnable(GL_LIGHT0 + li);
      L.eyePosition = vertex::transformPointLikeMesa(lightMv, pos);
      L.eyeSpotDirection = vertex::transformDirectionLikeMesa(lightMv, sdir);
    }
    glLoadMatrixf(&mv[0][0]);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, &la.model.ambient[0]);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, la.model.localViewer);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, la.model.twoSide);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, la.model.colorControl);
    if (ta.normalize)
      glEnable(GL_NORMALIZE);
    else
      glDisable(GL_NORMALIZE);
    if (ta.rescaleNormal)
      glEnable(GL_RESCALE_NORMAL);
    else
      glDisable(GL_RESCALE_NORMAL);
    glColorMaterial(la.colorMaterialFace, la.colorMaterialParameter);
    if (colorMaterial)
      glEnable(GL_COLOR_MATERIAL);
    else
      glDisable(GL_COLOR_MATERIAL);
    la.material[0] = randomMaterial(o);
    la.material[1] = P(0.5) ? randomMaterial(o) : la.material[0];
    for (int f = 0; f < 2; ++f) {
      const GLenum face = f ? GL_BACK : GL_FRONT;
      const Material& m = la.material[f];
      glMaterialfv(face, GL_AMBIENT, &m.ambient[0]);
      glMaterialfv(face, GL_DIFFUSE, &m.diffuse[0]);
      glMaterialfv(face, GL_SPECULAR, &m.specular[0]);
      glMaterialfv(face, GL_EMISSION, &m.emission[0]);
      glMaterialf(face, GL_SHININESS, m.shininess);
    }
    glEnable(GL_LIGHTING);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);

    // ---- vertices ----
    VertexBatch batch;
    batch.reset(GL_TRIANGLES, la.material);
    const glm::mat4 mvInv = glm::inverse(glm::dmat4(mv));
    std::vector<int> caseBack(W * H);
    glBegin(GL_TRIANGLES);
    for (int cy = 0; cy < H; ++cy)
      for (int cx = 0; cx < W; ++cx) {
        const bool back = la.model.twoSide && P(0.5);
        caseBack[cy * W + cx] = back;
        const float ez = U(-50, 50);
        const float wx[3] = {cx - 0.2f, back ? cx - 0.2f : cx + 1.4f, back ? cx + 1.4f : cx - 0.2f};
        const float wy[3] = {cy - 0.2f, back ? cy + 1.4f : cy - 0.2f, back ? cy - 0.2f : cy + 1.4f};
        if (beginEndMaterial) {
          MaterialPair mp;
          mp[0] = randomMaterial(o);
          mp[1] = P(1 - sameBack) ? randomMaterial(o) : mp[0];
          for (int f = 0; f < 2; ++f) {
            const GLenum face = f ? GL_BACK : GL_FRONT;
            Material& m = mp[f];
            const Material& prev = batch.materials.back()[f];
            if (subset[f] & vertex::kTrackAmbient)
              glMaterialfv(face, GL_AMBIENT, &m.ambient[0]);
            else
              m.ambient = prev.ambient;
            if (subset[f] & vertex::kTrackDiffuse)
              glMaterialfv(face, GL_DIFFUSE, &m.diffuse[0]);
            else
              m.diffuse = prev.diffuse;
            if (subset[f] & vertex::kTrackSpecular)
              glMaterialfv(face, GL_SPECULAR, &m.specular[0]);
            else
              m.specular = prev.specular;
            if (subset[f] & vertex::kTrackEmission)
              glMaterialfv(face, GL_EMISSION, &m.emission[0]);
            else
              m.emission = prev.emission;
            if (subset[f] & vertex::kMaterialShininess)
              glMaterialf(face, GL_SHININESS, m.shininess);
            else
              m.shininess = prev.shininess;
          }
          // Tracked components are not changed by glMaterial.
          if (colorMaterial) {
            const uint32_t bits = vertex::colorMaterialBits(la.colorMaterialFace, la.colorMaterialParameter);
            for (int f = 0; f < 2; ++f) {
              uint32_t b = bits >> (vertex::kTrackBackShift * f);
              if (b & vertex::kTrackEmission) mp[f].emission = batch.materials.back()[f].emission;
              if (b & vertex::kTrackAmbient) mp[f].ambient = batch.materials.back()[f].ambient;
              if (b & vertex::kTrackDiffuse) mp[f].diffuse = batch.materials.back()[f].diffuse;
              if (b & vertex::kTrackSpecular) mp[f].specular = batch.materials.back()[f].specular;
            }
          }
          batch.materials.push_back(mp);
        }
        for (int v = 0; v < 3; ++v) {
          const bool lit = v == 2;
          vec3 n = lit ? randDir() * (P(o.pUnitNormal) ? 1.0f : U(0.3f, 1.7f)) : vec3(0, 0, 1);
          vec4 color = randColor(0, 1);
          const double ndcx = (wx[v] / W) * 2 - 1, ndcy = (wy[v] / H) * 2 - 1;
          glm::dvec4 obj = glm::dmat4(mvInv) * glm::dvec4(ndcx, ndcy, ez, 1);
          vec4 objf(obj);
          if (getenv("WRAND")) objf *= U(0.5f, 2.0f);  // same window position, V.w != 1
          glNormal3fv(&n[0]);
          glColor4fv(&color[0]);
          glVertex4fv(&objf[0]);
          batch.position.push_back(objf);
          batch.normal.push_back(n);
          batch.color.push_back(color);
          batch.materialIndex.push_back(uint32_t(batch.materials.size() - 1));
        }
      }
    glEnd();
    glFinish();

    if (const char* alt = getenv("ALT")) {
      int a = atoi(alt);
      std::vector<MaterialPair> orig = batch.materials;
      for (size_t m = 1; m < batch.materials.size(); ++m) {
        if (a == 1) batch.materials[m][1] = orig[m][0];
        if (a == 2) batch.materials[m][1] = orig[m - 1][1];
        if (a == 3) batch.materials[m][1] = orig[0][1];
        if (a == 4) batch.materials[m][1] = orig[m - 1][0];
      }
    }
    if (beginEndMaterial) {
      const uint32_t all = vertex::kTrackEmission | vertex::kTrackAmbient | vertex::kTrackDiffuse |
                           vertex::kTrackSpecular | vertex::kMaterialShininess;
      uint32_t t =
          colorMaterial ? vertex::colorMaterialBits(la.colorMaterialFace, la.colorMaterialParameter) : 0;
      la.beginEndMaterialMask = ((all & subset[0]) | ((all & subset[1]) << vertex::kTrackBackShift)) & ~t;
    }
    // ---- mine ----
    vertex::LightingConstants k;
    vertex::buildLightingConstants(la, ta, k);
    vertex::VertexState vs;
    vs.eyeFromObject = mv;
    vs.lighting = true;
    vs.lightingConstants = &k;
    vs.lightingAttrib = &la;
    vs.transformAttrib = &ta;
    ShadedVertices out;
    vertex::lightBatch(vs, batch, out);
    long frameMism = 0;
    for (int cy = 0; cy < H; ++cy)
      for (int cx = 0; cx < W; ++cx) {
        const int c = cy * W + cx;
        const size_t vi = size_t(c) * 3 + 2;
        const int face = caseBack[c] ? 1 : 0;
        vec4 col = out.primary[face][vi];
        if (out.hasSecondary)
          col = glm::clamp(col + vec4(vec3(out.secondary[face][vi]), 0), vec4(0), vec4(1));
        const unsigned char* px = &buf[(cy * W + cx) * 4];
        bool bad = false;
        for (int ch = 0; ch < 4; ++ch) {
          int mine = (int)rintf(col[ch] * 255.0f);
          int d = std::abs(mine - px[ch]);
          if (d) {
            bad = true;
            ++mismChannels;
            maxDiff = std::max<long>(maxDiff, d);
          }
        }
        ++total;
        if (bad) {
          ++mism;
          ++frameMism;
          if (verbose && frameMism <= 5)
            printf(
                "frame %d case %d,%d face %d: mesa %d %d %d %d mine %.6f %.6f %.6f %.6f (x255 %.3f %.3f "
                "%.3f)\n",
                frame, cx, cy, face, px[0], px[1], px[2], px[3], col[0], col[1], col[2], col[3], col[0] * 255,
                col[1] * 255, col[2] * 255);
        }
      }
    if (verbose || frameMism)
      printf(
          "frame %d: mv %d lights %d lv %d two %d sep %d norm %d resc %d shin %g/%g bem %d cm %d: %ld "
          "mismatches\n",
          frame, mvKind, nl, la.model.localViewer, la.model.twoSide,
          la.model.colorControl == GL_SEPARATE_SPECULAR_COLOR, ta.normalize, ta.rescaleNormal,
          la.material[0].shininess, la.material[1].shininess, beginEndMaterial, colorMaterial, frameMism);
  }
  printf("preset %s seed %u: %ld cases, %ld mismatching pixels (%.4f%%), %ld channels, max diff %ld\n",
         preset.c_str(), seed, total, mism, 100.0 * mism / total, mismChannels, maxDiff);
  return 0;
}
