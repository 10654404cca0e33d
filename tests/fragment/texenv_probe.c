/* The texture environment on Mesa (OSMesa, llvmpipe): random environments of
 * up to three units (units 0 and 1 enabled or not, unit 2 never: a crossbar
 * source may name it), each drawn over a 16x16 region whose pixels read
 * their own texel of a 16x16 GL_NEAREST texture per unit and their own
 * constant primary colour (glColor4ub, flat). Prints every environment and,
 * per pixel, the texels as the sampler returns them (base format applied),
 * the primary colour and the colour read back; texenv_test.cpp recomputes
 * each with applyTexEnv. Usage: texenv_probe SEED CONFIGS */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kUnits = 3, kRegion = 16, kRegionsX = 4, kSize = kRegion * kRegionsX, kBatch = kRegionsX * kRegionsX };

static unsigned long long rng_state;
static unsigned next_rand(void) {
  rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
  return (unsigned)(rng_state >> 33);
}
static unsigned pick(unsigned n) { return next_rand() % n; }

typedef struct {
  int enabled;
  GLenum internal_format, base_format, mode, combine_rgb, combine_alpha;
  GLenum source_rgb[3], source_alpha[3], operand_rgb[3], operand_alpha[3];
  int rgb_scale, alpha_scale;
  float color[4];
  unsigned char texels[kRegion * kRegion][4]; /* as uploaded: RGBA bytes */
} Unit;

typedef struct {
  Unit unit[kUnits];
  unsigned char primary[kRegion * kRegion][4];
} Config;

static const GLenum kFormats[][2] = {{GL_RGBA8, GL_RGBA},
                                     {GL_RGB8, GL_RGB},
                                     {GL_ALPHA8, GL_ALPHA},
                                     {GL_LUMINANCE8, GL_LUMINANCE},
                                     {GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA},
                                     {GL_INTENSITY8, GL_INTENSITY}};
static const GLenum kModes[] = {GL_REPLACE, GL_MODULATE, GL_DECAL,   GL_BLEND,
                                GL_ADD,     GL_COMBINE,  GL_COMBINE, GL_COMBINE};
static const GLenum kCombineRGB[] = {GL_REPLACE,     GL_MODULATE, GL_ADD,      GL_ADD_SIGNED,
                                     GL_INTERPOLATE, GL_SUBTRACT, GL_DOT3_RGB, GL_DOT3_RGBA};
static const GLenum kCombineAlpha[] = {GL_REPLACE,    GL_MODULATE,    GL_ADD,
                                       GL_ADD_SIGNED, GL_INTERPOLATE, GL_SUBTRACT};
static const GLenum kSources[] = {GL_TEXTURE,  GL_CONSTANT, GL_PRIMARY_COLOR, GL_PREVIOUS,
                                  GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE,       GL_PREVIOUS};
static const GLenum kOperandRGB[] = {GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA,
                                     GL_ONE_MINUS_SRC_ALPHA};
static const GLenum kOperandAlpha[] = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
static const int kScales[] = {1, 1, 2, 4};

/* A value of [0,1]: mostly an 8-bit one, sometimes any float, sometimes 0 or 1. */
static float random_unit_float(void) {
  switch (pick(4)) {
    case 0: return (float)(next_rand() & 0xffffff) / 16777215.0f;
    case 1: return (float)pick(2);
    default: return (float)pick(256) / 255.0f;
  }
}

static void random_config(Config* c, int crossbar_to_disabled) {
  memset(c, 0, sizeof *c);
  int mask = 1 + (int)pick(3); /* unit 0, unit 1, or both */
  for (int u = 0; u < kUnits; ++u) {
    Unit* t = &c->unit[u];
    t->enabled = u < 2 && ((mask >> u) & 1);
    const GLenum* f = kFormats[pick(6)];
    t->internal_format = f[0];
    t->base_format = f[1];
    t->mode = kModes[pick(8)];
    t->combine_rgb = kCombineRGB[pick(8)];
    t->combine_alpha = kCombineAlpha[pick(6)];
    unsigned nsources = crossbar_to_disabled ? 8 : 4; /* crossbar sources only in some */
    for (int n = 0; n < 3; ++n) {
      t->source_rgb[n] = kSources[pick(nsources)];
      t->source_alpha[n] = kSources[pick(nsources)];
      if (crossbar_to_disabled && pick(8) == 0) t->source_rgb[n] = GL_TEXTURE2;
      t->operand_rgb[n] = kOperandRGB[pick(4)];
      t->operand_alpha[n] = kOperandAlpha[pick(2)];
    }
    t->rgb_scale = kScales[pick(4)];
    t->alpha_scale = kScales[pick(4)];
    for (int k = 0; k < 4; ++k) t->color[k] = random_unit_float();
    for (int p = 0; p < kRegion * kRegion; ++p)
      for (int k = 0; k < 4; ++k) t->texels[p][k] = (unsigned char)pick(256);
  }
  for (int p = 0; p < kRegion * kRegion; ++p)
    for (int k = 0; k < 4; ++k) c->primary[p][k] = (unsigned char)pick(256);
}

/* The texel as the sampler returns it for the base format (table 3.15). */
static void sampled(const Unit* t, const unsigned char* in, unsigned char* out) {
  unsigned char r = in[0], g = in[1], b = in[2], a = in[3];
  switch (t->base_format) {
    case GL_RGBA: out[0] = r, out[1] = g, out[2] = b, out[3] = a; break;
    case GL_RGB: out[0] = r, out[1] = g, out[2] = b, out[3] = 255; break;
    case GL_ALPHA: out[0] = out[1] = out[2] = 0, out[3] = a; break;
    case GL_LUMINANCE: out[0] = out[1] = out[2] = r, out[3] = 255; break;
    case GL_LUMINANCE_ALPHA: out[0] = out[1] = out[2] = r, out[3] = a; break;
    default: out[0] = out[1] = out[2] = out[3] = r; break; /* intensity */
  }
}

static void upload(const Unit* t) {
  unsigned char data[kRegion * kRegion * 4];
  GLenum format = GL_RGBA;
  int n = kRegion * kRegion;
  for (int p = 0; p < n; ++p) {
    const unsigned char* s = t->texels[p];
    switch (t->base_format) {
      case GL_RGBA: memcpy(data + 4 * p, s, 4); break;
      case GL_RGB: memcpy(data + 3 * p, s, 3); break;
      case GL_ALPHA: data[p] = s[3]; break;
      case GL_LUMINANCE_ALPHA: data[2 * p] = s[0], data[2 * p + 1] = s[3]; break;
      default: data[p] = s[0]; break; /* luminance, intensity */
    }
  }
  switch (t->base_format) {
    case GL_RGB: format = GL_RGB; break;
    case GL_ALPHA: format = GL_ALPHA; break;
    case GL_LUMINANCE_ALPHA: format = GL_LUMINANCE_ALPHA; break;
    case GL_LUMINANCE:
    case GL_INTENSITY: format = GL_LUMINANCE; break;
    default: break;
  }
  glTexImage2D(GL_TEXTURE_2D, 0, (GLint)t->internal_format, kRegion, kRegion, 0, format, GL_UNSIGNED_BYTE,
               data);
}

static void set_env(const Unit* t) {
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)t->mode);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, t->color);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)t->combine_rgb);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)t->combine_alpha);
  for (int n = 0; n < 3; ++n) {
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + n, (GLint)t->source_rgb[n]);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + n, (GLint)t->source_alpha[n]);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + n, (GLint)t->operand_rgb[n]);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + n, (GLint)t->operand_alpha[n]);
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, t->rgb_scale);
  glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, t->alpha_scale);
}

static void draw(const Config* c, int region, GLuint* textures) {
  for (int u = 0; u < kUnits; ++u) {
    const Unit* t = &c->unit[u];
    glActiveTexture(GL_TEXTURE0 + u);
    set_env(t);
    if (t->enabled) {
      glBindTexture(GL_TEXTURE_2D, textures[u]);
      upload(t);
      glEnable(GL_TEXTURE_2D);
    } else {
      glDisable(GL_TEXTURE_2D);
    }
  }
  int ox = (region % kRegionsX) * kRegion, oy = (region / kRegionsX) * kRegion;
  glBegin(GL_QUADS);
  for (int py = 0; py < kRegion; ++py)
    for (int px = 0; px < kRegion; ++px) {
      const unsigned char* col = c->primary[py * kRegion + px];
      glColor4ub(col[0], col[1], col[2], col[3]);
      static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int v = 0; v < 4; ++v) {
        float s = (float)(px + corner[v][0]) / kRegion, tc = (float)(py + corner[v][1]) / kRegion;
        for (int u = 0; u < kUnits; ++u) glMultiTexCoord2f(GL_TEXTURE0 + u, s, tc);
        glVertex2i(ox + px + corner[v][0], oy + py + corner[v][1]);
      }
    }
  glEnd();
}

static void print_config(int id, const Config* c) {
  for (int u = 0; u < kUnits; ++u) {
    const Unit* t = &c->unit[u];
    printf("U %d %d %d 0x%x 0x%x 0x%x 0x%x", id, u, t->enabled, t->base_format, t->mode, t->combine_rgb,
           t->combine_alpha);
    for (int n = 0; n < 3; ++n)
      printf(" 0x%x 0x%x 0x%x 0x%x", t->source_rgb[n], t->source_alpha[n], t->operand_rgb[n],
             t->operand_alpha[n]);
    printf(" %d %d %a %a %a %a\n", t->rgb_scale, t->alpha_scale, t->color[0], t->color[1], t->color[2],
           t->color[3]);
  }
}

int main(int argc, char** argv) {
  if (argc < 3) return 2;
  rng_state = strtoull(argv[1], NULL, 10) * 2654435761ull + 1;
  int configs = atoi(argv[2]);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  static unsigned char buffer[kSize * kSize * 4];
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, kSize, kSize)) return 1;
  glViewport(0, 0, kSize, kSize);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, kSize, 0, kSize, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glShadeModel(GL_FLAT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  GLuint textures[kUnits];
  glGenTextures(kUnits, textures);
  for (int u = 0; u < kUnits; ++u) {
    glActiveTexture(GL_TEXTURE0 + u);
    glBindTexture(GL_TEXTURE_2D, textures[u]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  static Config batch[kBatch];
  for (int first = 0; first < configs; first += kBatch) {
    int n = configs - first < kBatch ? configs - first : kBatch;
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    for (int r = 0; r < n; ++r) {
      random_config(&batch[r], (first + r) % 4 == 3);
      draw(&batch[r], r, textures);
    }
    glFinish();
    for (int r = 0; r < n; ++r) {
      int id = first + r;
      print_config(id, &batch[r]);
      int ox = (r % kRegionsX) * kRegion, oy = (r / kRegionsX) * kRegion;
      for (int p = 0; p < kRegion * kRegion; ++p) {
        int px = p % kRegion, py = p / kRegion;
        const unsigned char* out = buffer + 4 * ((oy + py) * kSize + ox + px);
        printf("P %d", id);
        for (int u = 0; u < kUnits; ++u) {
          unsigned char s[4];
          sampled(&batch[r].unit[u], batch[r].unit[u].texels[p], s);
          printf(" %u %u %u %u", s[0], s[1], s[2], s[3]);
        }
        const unsigned char* col = batch[r].primary[p];
        printf(" %u %u %u %u %u %u %u %u\n", col[0], col[1], col[2], col[3], out[0], out[1], out[2], out[3]);
      }
    }
  }
  OSMesaDestroyContext(ctx);
  return 0;
}
