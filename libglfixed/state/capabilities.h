// The capabilities of glEnable/glDisable/glIsEnabled (GL 2.1 §2.14.1, table
// 6.x's "enable" rows): one table of capability -> where its flag lives, the
// glPushAttrib groups it belongs to, the derived state it dirties. glEnable,
// glDisable, glIsEnabled, glGet and the GL_ENABLE_BIT push and pop all read it,
// so adding a capability is one entry.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>

#include "state/attrib_groups.h"

namespace glfixed {

class Context;

struct Capability {
  GLenum cap;
  bool& (*flag)(Context&);
  // The groups besides GL_ENABLE_BIT that hold the flag (e.g. GL_DEPTH_BUFFER_BIT).
  GLbitfield groups;
  // The derived state to rebuild when it changes (state/dirty.h).
  uint32_t dirty;
  // False: the flag is state (queried, pushed, popped) but the stage that
  // uses it does not exist yet, so glEnable/glDisable refuse it with
  // GL_INVALID_ENUM rather than accept a capability that would draw nothing.
  bool settable;
  // A texture unit's enable: the flag is the active unit's; GL_ENABLE_BIT
  // saves every unit's (EnableAttrib::texture), not this flag.
  bool perTextureUnit;
};

// The number of entries in the table (checked where it is defined).
constexpr int kCapabilityCount = 73;

// Every capability, in table order.
const std::array<Capability, kCapabilityCount>& capabilities();
// The entry for `cap`, or null: not a capability (GL_INVALID_ENUM).
const Capability* findCapability(GLenum cap);

// Stores a capability's new value and marks its groups (GL_ENABLE_BIT too)
// and dirty bits. The caller has checked that the value changes and drawn
// the buffered vertices (api::beginStateChange's order).
void storeCapability(Context& ctx, const Capability& c, bool enabled);

// GL_ENABLE_BIT (table 6.x, "enable" column): every flag of the table, and
// every texture unit's enables.
struct EnableAttrib {
  std::array<bool, kCapabilityCount> flag{};
  std::array<TextureUnitEnables, kMaxTextureUnits> texture;
};

EnableAttrib saveEnables(Context& ctx);
// Restores each flag that differs, as glEnable/glDisable would (no flush: the
// caller has flushed).
void restoreEnables(Context& ctx, const EnableAttrib& saved);

}  // namespace glfixed
