// glfixed_clip_dump: the scene format of mesa_clip_dump.c (README.md), drawn
// with libglfixed's primitive and raster stages only (no GL API): the clip
// coordinates and colours go straight into primitive::drawPrimitives.
// Consecutive glBegin/glEnd blocks are merged the way Mesa's vbo merges them
// (primitive/merge.h). usage: glfixed_clip_dump scene.txt out.bin
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "framebuffer/framebuffer.h"
#include "primitive/merge.h"
#include "primitive/primitive.h"

using namespace glfixed;

static float rf(FILE* f) {
  char b[64];
  if (fscanf(f, "%63s", b) != 1) {
    fprintf(stderr, "eof\n");
    exit(1);
  }
  return strtof(b, nullptr);
}
static int ri(FILE* f) {
  int v;
  if (fscanf(f, "%i", &v) != 1) {
    fprintf(stderr, "eof int\n");
    exit(1);
  }
  return v;
}

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: glfixed_clip_dump scene.txt out.bin\n");
    return 2;
  }
  FILE* f = fopen(argv[1], "r");
  FILE* out = fopen(argv[2], "wb");
  if (!f || !out) {
    perror("glfixed_clip_dump");
    return 2;
  }
  char cmd[64];
  int W = 0, H = 0, depthBits = 24;
  std::vector<uint8_t> buf;
  Framebuffer fb;
  primitive::PrimitiveState ps;
  bool twoside = false, colorsum = false, constcolor = false;
  static uint32_t stipple[32];
  ShadedVertices pending;
  GLenum pendingMode = 0;
  bool havePending = false;
  auto flush = [&]() {
    if (!havePending) return;
    ps.mode = pendingMode;
    ps.raster.varyingCount = colorsum ? 8 : 4;
    ps.raster.scissorX0 = std::max(0, ps.viewportX);
    ps.raster.scissorY0 = std::max(0, ps.viewportY);
    ps.raster.scissorX1 = std::min(W, ps.viewportX + ps.viewportWidth);
    ps.raster.scissorY1 = std::min(H, ps.viewportY + ps.viewportHeight);
    primitive::drawPrimitives(ps, pending, fb);
    havePending = false;
  };
  while (fscanf(f, "%63s", cmd) == 1) {
    if (strcmp(cmd, "begin")) flush();
    if (!strcmp(cmd, "fb")) {
      W = ri(f);
      H = ri(f);
      depthBits = ri(f);
      if (depthBits == 32) depthBits = 24;
      buf.assign(size_t(W) * H * 4, 0);
      fb.color.pixels = buf.data();
      fb.color.width = W;
      fb.color.height = H;
      fb.color.rowLength = W;
      fb.color.setFormat(PixelFormat::kRGBA);
      fb.front = fb.readFront = fb.color;
      fb.depth.resize(W, H, depthBits);
      ps.viewportX = 0;
      ps.viewportY = 0;
      ps.viewportWidth = W;
      ps.viewportHeight = H;
    } else if (!strcmp(cmd, "clear")) {
      float c[4];
      for (float& x : c) x = rf(f);
      float d = rf(f);
      uint8_t rgba[4];
      for (int k = 0; k < 4; ++k) rgba[k] = floatToUnorm8(c[k]);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) fb.color.write(x, y, rgba);
      if (depthBits && ps.raster.depthWrite) fb.depth.fill(depthToUnorm(d, depthBits));
    } else if (!strcmp(cmd, "shade")) {
      ps.flat = ri(f) != 0;
    } else if (!strcmp(cmd, "provoking")) {
      ps.firstVertexConvention = ri(f) != 0;
    } else if (!strcmp(cmd, "cull")) {
      ps.cullFace = ri(f) != 0;
      ps.cullFaceMode = ri(f);
      ps.frontFace = ri(f);
    } else if (!strcmp(cmd, "depth")) {
      ps.raster.depthTest = ri(f) != 0 && depthBits;
      ps.raster.depthFunc = ri(f);
      ps.raster.depthWrite = ri(f) != 0;
    } else if (!strcmp(cmd, "viewport")) {
      ps.viewportX = ri(f);
      ps.viewportY = ri(f);
      ps.viewportWidth = ri(f);
      ps.viewportHeight = ri(f);
    } else if (!strcmp(cmd, "range")) {
      ps.depthNear = rf(f);
      ps.depthFar = rf(f);
    } else if (!strcmp(cmd, "offset")) {
      // As pipeline/draw.cpp: any of the three enables offsets filled triangles.
      const int fill = ri(f), line = ri(f), point = ri(f);
      ps.raster.polygonOffset = fill || line || point;
      ps.raster.offsetFactor = rf(f);
      ps.raster.offsetUnits = rf(f);
      ps.offsetFill = fill;
      ps.offsetLine = line;
      ps.offsetPoint = point;
    } else if (!strcmp(cmd, "stipple")) {
      // As pipeline/draw.cpp: the pattern as glPolygonStipple unpacks it.
      const bool en = ri(f) != 0;
      unsigned seed = static_cast<unsigned>(ri(f));
      for (int row = 0; row < 32; ++row) {
        uint32_t w = 0;
        for (int k = 0; k < 4; ++k) {
          seed = seed * 1103515245u + 12345u;
          w = (w << 8) | ((seed >> 16) & 0xffu);
        }
        stipple[row] = w;
      }
      ps.polygonStipple = en;
      ps.raster.polygonStipple = en ? stipple : nullptr;
    } else if (!strcmp(cmd, "polymode")) {
      ps.polygonModeFront = ri(f);
      ps.polygonModeBack = ri(f);
    } else if (!strcmp(cmd, "smooth")) {
      const int pt = ri(f), ln = ri(f);
      ps.lineOrPointPipeline = pt || ln;  // as pipeline/draw.cpp
    } else if (!strcmp(cmd, "colorsum")) {
      colorsum = ri(f) != 0;
    } else if (!strcmp(cmd, "constcolor")) {
      constcolor = ri(f) != 0;
    } else if (!strcmp(cmd, "twoside")) {
      twoside = ri(f) != 0;
    } else if (!strcmp(cmd, "begin")) {
      GLenum mode = ri(f);
      int n = ri(f);
      ShadedVertices sv;
      sv.hasBack = twoside;
      sv.hasSecondary = colorsum;
      for (int i = 0; i < n; ++i) {
        float p[4], c[4], s[3], b[4];
        for (float& x : p) x = rf(f);
        for (float& x : c) x = rf(f);
        for (float& x : s) x = rf(f);
        for (float& x : b) x = rf(f);
        auto cl = [](float v) { return v < 0 ? 0.0f : (v > 1 ? 1.0f : v); };
        sv.clip.push_back(glm::vec4(p[0], p[1], p[2], p[3]));
        sv.primary[0].push_back(glm::vec4(cl(c[0]), cl(c[1]), cl(c[2]), cl(c[3])));
        sv.primary[1].push_back(glm::vec4(cl(b[0]), cl(b[1]), cl(b[2]), cl(b[3])));
        sv.secondary[0].push_back(twoside ? glm::vec4(0) : glm::vec4(cl(s[0]), cl(s[1]), cl(s[2]), 0));
        sv.secondary[1].push_back(glm::vec4(0));
      }
      const bool constant = constcolor && !twoside;  // Mesa reads the colours as constants
      if (constant)
        for (int i = 1; i < n; ++i) {
          sv.primary[0][i] = sv.primary[0][0];
          sv.secondary[0][i] = sv.secondary[0][0];
        }
      ps.constantPrimary = ps.constantSecondary = constant;
      if (constcolor) flush();  // Mesa side: a state change before every block, nothing merges
      mode = primitive::mesaConvertedMode(mode, n);
      if (havePending && primitive::mesaMergesPrimitives(pendingMode, pending.size(), mode)) {
        for (int i = 0; i < n; ++i) {
          pending.clip.push_back(sv.clip[i]);
          for (int k = 0; k < 2; ++k) {
            pending.primary[k].push_back(sv.primary[k][i]);
            pending.secondary[k].push_back(sv.secondary[k][i]);
          }
        }
      } else {
        flush();
        pending = sv;
        pendingMode = mode;
        havePending = true;
      }
    } else if (!strcmp(cmd, "dump")) {
      fwrite(&W, 4, 1, out);
      fwrite(&H, 4, 1, out);
      fwrite(buf.data(), 4, size_t(W) * H, out);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          uint32_t v = depthBits ? fb.depth.get(x, y) : 0;
          fwrite(&v, 4, 1, out);
        }
    } else {
      fprintf(stderr, "unknown %s\n", cmd);
      return 1;
    }
  }
  fclose(out);
}
