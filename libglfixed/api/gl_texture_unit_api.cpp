// glActiveTexture (GL 2.1 §3.8.15, §2.7): which texture unit the texture
// commands (glBindTexture, glTexEnv, glTexGen, the texture matrix, the
// GL_TEXTURE_xD enables) address. The client-side selector,
// glClientActiveTexture, is with the arrays (api/gl_array_api.cpp).
#include "api/api.h"
#include "api/list_record.h"

extern "C" {

GLAPI void APIENTRY glActiveTexture(GLenum texture) {
  if (glfixed::api::compiled(&glActiveTexture, texture)) return;
  glfixed::Context* ctx = glfixed::api::contextForSetter();
  if (!ctx) return;
  // The units this library offers are fixed-function units: GL_MAX_TEXTURE_UNITS
  // of them (Mesa accepts up to its combined image units, which only shaders use).
  if (texture < GL_TEXTURE0 || texture >= GL_TEXTURE0 + glfixed::kMaxTextureUnits) {
    ctx->recordError(GL_INVALID_ENUM);
    return;
  }
  glfixed::api::setState(*ctx, ctx->texture.activeTexture, texture, GL_TEXTURE_BIT);
}

}  // extern "C"
