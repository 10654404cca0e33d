// Multisample state (GL 2.1 §3.2.1, §4.1.3): glSampleCoverage. Every
// surface has GL_SAMPLE_BUFFERS 0, so the coverage value, like the
// GL_MULTISAMPLE and GL_SAMPLE_* enables, is state that changes nothing drawn.
#include "api/api.h"
#include "api/list_record.h"

using namespace glfixed;

extern "C" {

GLAPI void APIENTRY glSampleCoverage(GLfloat value, GLboolean invert) {
  if (api::compiled(&glSampleCoverage, value, invert)) return;
  Context* ctx = api::contextForSetter();
  if (!ctx) return;
  MultisampleAttrib& m = ctx->multisample;
  const float v = api::clamp01(value);  // NaN -> 0
  if (m.sampleCoverageValue == v && m.sampleCoverageInvert == invert) return;
  api::beginStateChange(*ctx, GL_MULTISAMPLE_BIT);
  m.sampleCoverageValue = v;
  m.sampleCoverageInvert = invert;  // kept as given (Mesa returns 7 for 7)
}

// ARB_multisample's name.
GLAPI void APIENTRY glSampleCoverageARB(GLfloat value, GLboolean invert) { glSampleCoverage(value, invert); }

}  // extern "C"
