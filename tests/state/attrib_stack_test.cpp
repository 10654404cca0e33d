// The capability table and the attribute stack's group table agree: every
// capability is restored by GL_ENABLE_BIT and by each group its entry names,
// which must be the group whose struct holds its flag; and by no other group.
// Reaches the capabilities glEnable still refuses (their stages come later).
#include "state/attrib_stack.h"

#include <gtest/gtest.h>

#include "state/capabilities.h"
#include "state/context.h"

namespace glfixed {
namespace {

const GLbitfield kGroups[] = {
    GL_CURRENT_BIT,        GL_POINT_BIT,    GL_LINE_BIT,      GL_POLYGON_BIT,      GL_POLYGON_STIPPLE_BIT,
    GL_PIXEL_MODE_BIT,     GL_LIGHTING_BIT, GL_FOG_BIT,       GL_DEPTH_BUFFER_BIT, GL_ACCUM_BUFFER_BIT,
    GL_STENCIL_BUFFER_BIT, GL_VIEWPORT_BIT, GL_TRANSFORM_BIT, GL_ENABLE_BIT,       GL_COLOR_BUFFER_BIT,
    GL_HINT_BIT,           GL_SCISSOR_BIT,  GL_TEXTURE_BIT,   GL_MULTISAMPLE_BIT,
};

TEST(CapabilityTable, EveryCapabilityIsRestoredByExactlyItsGroups) {
  for (const Capability& c : capabilities()) {
    for (GLbitfield g : kGroups) {
      SCOPED_TRACE(::testing::Message() << "cap 0x" << std::hex << c.cap << ", group 0x" << g);
      Context ctx(24);
      const bool initial = c.flag(ctx);
      ASSERT_TRUE(ctx.attribStack.push(ctx, g));
      storeCapability(ctx, c, !initial);
      EXPECT_NE(ctx.attribGroupsChanged & GL_ENABLE_BIT, 0u);
      ASSERT_TRUE(ctx.attribStack.pop(ctx));
      const bool holds = (g == GL_ENABLE_BIT) || (c.groups & g);
      EXPECT_EQ(c.flag(ctx), holds ? initial : !initial);
    }
  }
}

TEST(CapabilityTable, EachCapabilityOnceWithItsOwnFlag) {
  Context ctx(24);
  for (const Capability& a : capabilities()) {
    EXPECT_EQ(findCapability(a.cap), &a);
    for (const Capability& b : capabilities())
      if (&a != &b) EXPECT_NE(&a.flag(ctx), &b.flag(ctx)) << std::hex << a.cap << " " << b.cap;
  }
  EXPECT_EQ(findCapability(GL_LIGHT0 + 8), nullptr);
  EXPECT_EQ(findCapability(GL_TEXTURE_ENV), nullptr);
}

// glPopAttrib restores only the groups changed since the push; the others
// already hold the pushed values. Not observable through the GL (a copy of
// equal values), so checked here: the changed-groups mask is what Mesa's
// PopAttribState would be.
TEST(AttribStack, ChangedGroupsAreTrackedAcrossNestedPushes) {
  Context ctx(24);
  ctx.markChanged(GL_FOG_BIT, 0);
  ASSERT_TRUE(ctx.attribStack.push(ctx, GL_DEPTH_BUFFER_BIT));
  EXPECT_EQ(ctx.attribGroupsChanged, 0u);
  ctx.markChanged(GL_DEPTH_BUFFER_BIT | GL_LINE_BIT, 0);
  ASSERT_TRUE(ctx.attribStack.push(ctx, GL_LINE_BIT));
  ctx.markChanged(GL_HINT_BIT, 0);
  ASSERT_TRUE(ctx.attribStack.pop(ctx));
  // The inner push's mask is cleared, what changed before it comes back.
  EXPECT_EQ(ctx.attribGroupsChanged, GLbitfield(GL_DEPTH_BUFFER_BIT | GL_LINE_BIT | GL_HINT_BIT));
  ASSERT_TRUE(ctx.attribStack.pop(ctx));
  EXPECT_EQ(ctx.attribGroupsChanged, GLbitfield(GL_FOG_BIT | GL_LINE_BIT | GL_HINT_BIT));
  EXPECT_FALSE(ctx.attribStack.pop(ctx));
}

TEST(AttribStack, HoldsSixteen) {
  Context ctx(24);
  for (int i = 0; i < kMaxAttribStackDepth; ++i) EXPECT_TRUE(ctx.attribStack.push(ctx, GL_ALL_ATTRIB_BITS));
  EXPECT_FALSE(ctx.attribStack.push(ctx, GL_ALL_ATTRIB_BITS));
  EXPECT_EQ(ctx.attribStack.depth(), kMaxAttribStackDepth);
}

}  // namespace
}  // namespace glfixed
