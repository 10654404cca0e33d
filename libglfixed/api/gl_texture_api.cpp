// Texture objects (GL 2.1 §3.8.12): glGenTextures, glBindTexture,
// glDeleteTextures, glIsTexture, glPrioritizeTextures,
// glAreTexturesResident. The name space is texture/texture_objects.h; the
// images are api/gl_tex_image_api.cpp, the parameters
// api/gl_tex_parameter_api.cpp.
#include "api/api.h"
#include "api/framebuffer_object_commands.h"
#include "api/list_record.h"
#include "texture/texture_objects.h"

using namespace glfixed;

namespace {

size_t countOf(GLsizei n) { return n > 0 ? static_cast<size_t>(n) : 0; }

}  // namespace

extern "C" {

GLAPI void APIENTRY glGenTextures(GLsizei n, GLuint* textures) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!textures) return;
  ctx->textures->generate(n, textures);
}

GLAPI void APIENTRY glBindTexture(GLenum target, GLuint texture) {
  if (api::compiled(&glBindTexture, target, texture)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  const int index = texture::targetIndex(target);
  if (index < 0) return ctx->recordError(GL_INVALID_ENUM);
  if (texture != 0) {
    // A name's target is fixed when it is first bound (§3.8.12).
    texture::TextureObject* object = ctx->textures->find(texture);
    if (object && object->target != 0 && object->target != target)
      return ctx->recordError(GL_INVALID_OPERATION);
  }
  GLuint& binding = texture::bindingOf(ctx->texture.binding[ctx->texture.activeUnit()], index);
  if (binding == texture && (texture == 0 || ctx->textures->find(texture))) return;
  api::beginStateChange(*ctx, GL_TEXTURE_BIT);
  if (texture != 0) {
    texture::TextureObject* object = ctx->textures->obtain(texture);
    if (object->target == 0) {
      object->target = target;
      // A rectangle-free GL 2.1: every target starts with the same
      // parameters (table 6.23), nothing to set per target.
    }
  }
  binding = texture;
}

GLAPI void APIENTRY glDeleteTextures(GLsizei n, const GLuint* textures) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!textures) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = textures[i];
    if (name == 0 || !ctx->textures->find(name)) {
      if (name != 0) ctx->textures->remove(name);  // a generated, unbound name is freed too
      continue;
    }
    // Deleting a bound texture binds 0 in its place, in every unit of this
    // context (§3.8.12).
    for (TextureBindings& unit : ctx->texture.binding) {
      for (int index = 0; index < texture::kTargetCount; ++index) {
        GLuint& binding = texture::bindingOf(unit, index);
        if (binding != name) continue;
        api::beginStateChange(*ctx, GL_TEXTURE_BIT);
        binding = 0;
      }
    }
    pipeline::flushVertices(*ctx);  // the buffered vertices may sample it
    api::textureDeleted(*ctx, name);  // framebuffer objects: detached from the bound ones
    ctx->textures->remove(name);
  }
}

GLAPI GLboolean APIENTRY glIsTexture(GLuint texture) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  const texture::TextureObject* object = ctx->textures->find(texture);
  // A generated name becomes a texture when it is first bound.
  return object && object->target != 0 ? GL_TRUE : GL_FALSE;
}

// Priorities (§3.8.12) are kept and reported; residency is always true
// (all textures are in memory), as Mesa says.
GLAPI void APIENTRY glPrioritizeTextures(GLsizei n, const GLuint* textures, const GLclampf* priorities) {
  if (api::compiled(&glPrioritizeTextures, n, api::copied(textures, countOf(n)),
                    api::copied(priorities, countOf(n))))
    return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  if (n < 0) return ctx->recordError(GL_INVALID_VALUE);
  if (!textures || !priorities) return;
  for (GLsizei i = 0; i < n; ++i) {
    if (textures[i] == 0) continue;  // the default textures are skipped (Mesa: no error)
    if (texture::TextureObject* object = ctx->textures->find(textures[i])) {
      pipeline::flushVertices(*ctx);
      object->priority = api::clamp01(priorities[i]);
    }
  }
}

GLAPI GLboolean APIENTRY glAreTexturesResident(GLsizei n, const GLuint* textures, GLboolean* residences) {
  Context* ctx = api::contextForQuery();
  if (!ctx) return GL_FALSE;
  if (n < 0) {
    ctx->recordError(GL_INVALID_VALUE);
    return GL_FALSE;
  }
  if (!textures) return GL_FALSE;
  // Every name must be a texture (0 is not one): GL_INVALID_VALUE otherwise.
  // All being resident, `residences` is left as it is and GL_TRUE returned.
  for (GLsizei i = 0; i < n; ++i) {
    const texture::TextureObject* object = textures[i] ? ctx->textures->find(textures[i]) : nullptr;
    if (!object || object->target == 0) {
      ctx->recordError(GL_INVALID_VALUE);
      return GL_FALSE;
    }
  }
  (void)residences;
  return GL_TRUE;
}

}  // extern "C"
