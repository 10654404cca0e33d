// Mapped ranges (ARB_map_buffer_range) and copies between buffers
// (ARB_copy_buffer), GL 3.0/3.1 §2.10, with the errors Mesa gives in the
// order it checks them: every expectation here was measured on Mesa 22.3
// (reference/MESA_FACTS.md, "Buffer ranges and copies").
#include "api/gl_test_fixture.h"

// GL 3.0's queries of a mapping; the project's GL 2.1 header does not name them.
#ifndef GL_BUFFER_ACCESS_FLAGS
#define GL_BUFFER_ACCESS_FLAGS 0x911F
#define GL_BUFFER_MAP_LENGTH 0x9120
#define GL_BUFFER_MAP_OFFSET 0x9121
#endif
// GL 3.1's names of the copy bindings' queries (ARB_copy_buffer queries the targets).
#ifndef GL_COPY_READ_BUFFER_BINDING
#define GL_COPY_READ_BUFFER_BINDING GL_COPY_READ_BUFFER
#define GL_COPY_WRITE_BUFFER_BINDING GL_COPY_WRITE_BUFFER
#endif

using namespace glfx_test;

namespace {

class BufferRangeTest : public GLTest {
 protected:
  // A 64-byte buffer holding 0..63, bound to `target`.
  GLuint MakeBuffer(GLenum target, GLsizeiptr size = 64) {
    GLuint b = 0;
    glGenBuffers(1, &b);
    glBindBuffer(target, b);
    std::vector<unsigned char> bytes(static_cast<size_t>(size));
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i);
    glBufferData(target, size, bytes.data(), GL_STATIC_DRAW);
    return b;
  }
};

GLint BufferParam(GLenum target, GLenum pname) {
  GLint v = -12345;
  glGetBufferParameteriv(target, pname, &v);
  return v;
}

std::vector<unsigned char> BufferBytes(GLenum target, GLsizeiptr size) {
  std::vector<unsigned char> bytes(static_cast<size_t>(size), 0xEE);
  glGetBufferSubData(target, 0, size, bytes.data());
  return bytes;
}

void* MapPointer(GLenum target) {
  void* p = reinterpret_cast<void*>(0x1);
  glGetBufferPointerv(target, GL_BUFFER_MAP_POINTER, &p);
  return p;
}

// ---- glMapBufferRange ------------------------------------------------------------

TEST_F(BufferRangeTest, MapsTheRangeAndReportsIt) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH), 0);
  auto* p = static_cast<unsigned char*>(
      glMapBufferRange(GL_ARRAY_BUFFER, 16, 8, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT));
  ASSERT_NE(p, nullptr);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(p[0], 16);  // the pointer is the range's first byte
  EXPECT_EQ(p[7], 23);
  EXPECT_EQ(MapPointer(GL_ARRAY_BUFFER), p);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_TRUE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS), GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET), 16);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH), 8);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);
  for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(200 + i);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> bytes = BufferBytes(GL_ARRAY_BUFFER, 64);
  for (int i = 0; i < 64; ++i) EXPECT_EQ(bytes[i], i >= 16 && i < 24 ? 200 + i - 16 : i) << i;
  // Unmapped: the flags, offset and length are 0 again, the pointer null.
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH), 0);
  EXPECT_EQ(MapPointer(GL_ARRAY_BUFFER), nullptr);
  EXPECT_NO_GL_ERROR();
  glDeleteBuffers(1, &b);
}

// GL_BUFFER_ACCESS follows the read and write bits of the mapping, and is
// GL_READ_WRITE again once unmapped (Mesa; not the last glMapBuffer's).
TEST_F(BufferRangeTest, AccessFlagsOfEveryValidCombination) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  const struct {
    GLbitfield flags;
    GLenum access;
  } cases[] = {
      {GL_MAP_READ_BIT, GL_READ_ONLY},
      {GL_MAP_WRITE_BIT, GL_WRITE_ONLY},
      {GL_MAP_READ_BIT | GL_MAP_WRITE_BIT, GL_READ_WRITE},
      {GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT, GL_WRITE_ONLY},
      {GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT, GL_WRITE_ONLY},
      {GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT, GL_WRITE_ONLY},
      {GL_MAP_WRITE_BIT | GL_MAP_UNSYNCHRONIZED_BIT, GL_WRITE_ONLY},
      {GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT, GL_READ_WRITE},
      {GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_FLUSH_EXPLICIT_BIT |
           GL_MAP_UNSYNCHRONIZED_BIT,
       GL_WRITE_ONLY},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.flags);
    EXPECT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 8, 16, c.flags), nullptr);
    EXPECT_NO_GL_ERROR();
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS), static_cast<GLint>(c.flags));
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), static_cast<GLint>(c.access));
    EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), GL_READ_WRITE);
  }
  EXPECT_NO_GL_ERROR();
  glDeleteBuffers(1, &b);
}

// glMapBuffer maps the whole store with the flags of its access.
TEST_F(BufferRangeTest, MapBufferImpliesFlagsOverTheWholeStore) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  const GLenum access[] = {GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE};
  const GLint flags[] = {GL_MAP_READ_BIT, GL_MAP_WRITE_BIT, GL_MAP_READ_BIT | GL_MAP_WRITE_BIT};
  for (int i = 0; i < 3; ++i) {
    void* p = glMapBuffer(GL_ARRAY_BUFFER, access[i]);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(MapPointer(GL_ARRAY_BUFFER), p);
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS), flags[i]);
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET), 0);
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH), 64);
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS), static_cast<GLint>(access[i]));
    // No explicit flush on a glMapBuffer mapping; no second mapping either.
    glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, GL_MAP_READ_BIT), nullptr);
    EXPECT_GL_ERROR(GL_INVALID_OPERATION);
    EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  }
  // And a range mapping refuses glMapBuffer.
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 4, 4, GL_MAP_WRITE_BIT), nullptr);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_NO_GL_ERROR();
  glDeleteBuffers(1, &b);
}

// One error a call, the first Mesa checks: the target, the buffer, offset
// and length, an empty range, unknown bits, then the combinations of bits,
// the range against the size, and last a mapping already there.
TEST_F(BufferRangeTest, MapRangeErrorsInMesasOrder) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  const GLbitfield R = GL_MAP_READ_BIT, W = GL_MAP_WRITE_BIT;
  const struct {
    GLintptr offset;
    GLsizeiptr length;
    GLbitfield access;
    GLenum error;
  } cases[] = {
      {-1, 4, R, GL_INVALID_VALUE},
      {0, -1, R, GL_INVALID_VALUE},
      {-1, -1, 0x100, GL_INVALID_VALUE},
      {0, 0, R, GL_INVALID_OPERATION},      // an empty range
      {0, 0, 0x100, GL_INVALID_OPERATION},  // before the bits
      {0, 4, R | 0x100, GL_INVALID_VALUE},  // a bit no extension defines
      {0, 4, R | 0x40, GL_INVALID_OPERATION},  // GL_MAP_PERSISTENT_BIT: not a glBufferStorage store
      {0, 4, R | 0x80, GL_INVALID_OPERATION},  // GL_MAP_COHERENT_BIT
      {0, 4, 0, GL_INVALID_OPERATION},         // neither read nor write
      {0, 100, 0, GL_INVALID_OPERATION},       // before the size
      {0, 4, R | GL_MAP_INVALIDATE_RANGE_BIT, GL_INVALID_OPERATION},
      {0, 4, R | GL_MAP_INVALIDATE_BUFFER_BIT, GL_INVALID_OPERATION},
      {0, 4, R | GL_MAP_UNSYNCHRONIZED_BIT, GL_INVALID_OPERATION},
      {0, 4, R | W | GL_MAP_INVALIDATE_RANGE_BIT, GL_INVALID_OPERATION},
      {0, 4, R | GL_MAP_FLUSH_EXPLICIT_BIT, GL_INVALID_OPERATION},  // flush without write
      {0, 65, R | GL_MAP_FLUSH_EXPLICIT_BIT, GL_INVALID_OPERATION},
      {0, 65, R, GL_INVALID_VALUE},
      {64, 1, R, GL_INVALID_VALUE},
      {60, 5, W, GL_INVALID_VALUE},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::Message() << c.offset << " " << c.length << " 0x" << std::hex << c.access);
    EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, c.offset, c.length, c.access), nullptr);
    EXPECT_GL_ERROR(c.error);
    EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  }
  // The whole store and its last byte are in range.
  EXPECT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 0, 64, R), nullptr);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 63, 1, W), nullptr);
  EXPECT_NO_GL_ERROR();
  // Mapped already: GL_INVALID_OPERATION, after the range check.
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, R), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, 0), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 100, R), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET), 63);  // the first mapping stays
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  // The target, then the buffer, come before everything else.
  EXPECT_EQ(glMapBufferRange(GL_RGBA, -1, 4, 0), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, -1, 4, R), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 4, R), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDeleteBuffers(1, &b);
}

// An empty store has no range to map: glMapBuffer of it fails too (Mesa).
TEST_F(BufferRangeTest, AnEmptyStoreCannotBeMapped) {
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE), nullptr);  // never given a store
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBufferData(GL_ARRAY_BUFFER, 0, nullptr, GL_STATIC_DRAW);
  EXPECT_EQ(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_FALSE);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 0, GL_MAP_READ_BIT), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glMapBufferRange(GL_ARRAY_BUFFER, 0, 1, GL_MAP_READ_BIT), nullptr);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glDeleteBuffers(1, &b);
}

// The invalidate and unsynchronized bits leave the old contents: what the
// mapping shows, and every byte not written, is what the store held (after
// a draw from the buffer too).
TEST_F(BufferRangeTest, InvalidatingKeepsTheOldBytes) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  const GLbitfield W = GL_MAP_WRITE_BIT;
  const GLbitfield cases[] = {W,
                              W | GL_MAP_INVALIDATE_RANGE_BIT,
                              W | GL_MAP_INVALIDATE_BUFFER_BIT,
                              W | GL_MAP_UNSYNCHRONIZED_BIT,
                              W | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT,
                              W | GL_MAP_FLUSH_EXPLICIT_BIT};
  unsigned char original[64];
  for (int i = 0; i < 64; ++i) original[i] = static_cast<unsigned char>(i);
  for (int drawFirst = 0; drawFirst < 2; ++drawFirst) {
    for (GLbitfield access : cases) {
      SCOPED_TRACE(::testing::Message() << "access 0x" << std::hex << access << " draw " << drawFirst);
      glBufferSubData(GL_ARRAY_BUFFER, 0, 64, original);
      if (drawFirst) {
        glVertexPointer(2, GL_FLOAT, 0, nullptr);
        glEnableClientState(GL_VERTEX_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisableClientState(GL_VERTEX_ARRAY);
      }
      auto* p = static_cast<unsigned char*>(glMapBufferRange(GL_ARRAY_BUFFER, 16, 16, access));
      ASSERT_NE(p, nullptr);
      for (int i = 0; i < 16; ++i) EXPECT_EQ(p[i], 16 + i);
      for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(200 + i);
      // An explicit flush of part of what was written: all of it lands.
      if (access & GL_MAP_FLUSH_EXPLICIT_BIT) glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 2);
      EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
      const std::vector<unsigned char> bytes = BufferBytes(GL_ARRAY_BUFFER, 64);
      for (int i = 0; i < 64; ++i) EXPECT_EQ(bytes[i], i >= 16 && i < 24 ? 200 + i - 16 : i) << i;
      EXPECT_NO_GL_ERROR();
    }
  }
  // The whole store, invalidated: its bytes are still there.
  glBufferSubData(GL_ARRAY_BUFFER, 0, 64, original);
  auto* p = static_cast<unsigned char*>(
      glMapBufferRange(GL_ARRAY_BUFFER, 0, 64, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT));
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p[1], 1);
  EXPECT_EQ(p[63], 63);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_EQ(BufferBytes(GL_ARRAY_BUFFER, 64), std::vector<unsigned char>(original, original + 64));
  glDeleteBuffers(1, &b);
}

// ---- glFlushMappedBufferRange ------------------------------------------------------

// Offsets are within the mapped range; the errors in Mesa's order: the
// buffer, offset and length, a mapping with GL_MAP_FLUSH_EXPLICIT_BIT, the
// range against the mapping's length.
TEST_F(BufferRangeTest, FlushMappedRangeErrors) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);  // not mapped
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, -1, 4);  // offset first
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFlushMappedBufferRange(GL_RGBA, -1, 4);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 16, 8, GL_MAP_READ_BIT), nullptr);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 4);  // no explicit flush asked for
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, -1, 4);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, -1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 8, 16, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT), nullptr);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, 16);
  EXPECT_NO_GL_ERROR();
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 16, 0);
  EXPECT_NO_GL_ERROR();
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 8, 9);  // past the mapped length, not the store
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 17, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, -1, 0);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  // Any binding of the buffer reaches its mapping.
  glBindBuffer(GL_COPY_WRITE_BUFFER, b);
  glFlushMappedBufferRange(GL_COPY_WRITE_BUFFER, 0, 4);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glUnmapBuffer(GL_COPY_WRITE_BUFFER), GL_TRUE);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, -1, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glDeleteBuffers(1, &b);
}

// ---- a mapped range and the other commands ------------------------------------------------------

// glBufferSubData may write outside the mapped range (Mesa); inside it, or
// any glGetBufferSubData while mapped, is GL_INVALID_OPERATION.
TEST_F(BufferRangeTest, SubDataBesideAMappedRange) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 16, 8, GL_MAP_READ_BIT), nullptr);
  const unsigned char nines[4] = {9, 9, 9, 9};
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, nines);
  EXPECT_NO_GL_ERROR();
  glBufferSubData(GL_ARRAY_BUFFER, 12, 4, nines);  // ends where the range starts
  EXPECT_NO_GL_ERROR();
  glBufferSubData(GL_ARRAY_BUFFER, 24, 4, nines);  // starts where it ends
  EXPECT_NO_GL_ERROR();
  glBufferSubData(GL_ARRAY_BUFFER, 14, 4, nines);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBufferSubData(GL_ARRAY_BUFFER, 23, 1, nines);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glBufferSubData(GL_ARRAY_BUFFER, 60, 8, nines);  // the size first
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  unsigned char back[4];
  glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, back);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  const std::vector<unsigned char> bytes = BufferBytes(GL_ARRAY_BUFFER, 64);
  for (int i = 0; i < 64; ++i)
    EXPECT_EQ(bytes[i], (i < 4 || (i >= 12 && i < 16) || (i >= 24 && i < 28)) ? 9 : i) << i;
  glDeleteBuffers(1, &b);
}

// glBufferData replaces the store and ends the mapping, without an error.
TEST_F(BufferRangeTest, BufferDataEndsTheMapping) {
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 4, 4, GL_MAP_READ_BIT), nullptr);
  glBufferData(GL_ARRAY_BUFFER, 32, nullptr, GL_DYNAMIC_DRAW);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_FLAGS), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_OFFSET), 0);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH), 0);
  EXPECT_EQ(MapPointer(GL_ARRAY_BUFFER), nullptr);
  // Deleting a mapped buffer is no error either.
  ASSERT_NE(glMapBufferRange(GL_ARRAY_BUFFER, 4, 4, GL_MAP_WRITE_BIT), nullptr);
  glDeleteBuffers(1, &b);
  EXPECT_NO_GL_ERROR();
}

// The buffer, GL_INVALID_OPERATION for 0, before the pname.
TEST_F(BufferRangeTest, BufferParameterChecksTheBufferBeforeThePname) {
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_RGBA), -12345);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(BufferParam(GL_RGBA, GL_RGBA), -12345);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_BUFFER_MAP_LENGTH), -12345);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  const GLuint b = MakeBuffer(GL_ARRAY_BUFFER);
  EXPECT_EQ(BufferParam(GL_ARRAY_BUFFER, GL_RGBA), -12345);
  EXPECT_GL_ERROR(GL_INVALID_ENUM);
  glDeleteBuffers(1, &b);
}

TEST_F(BufferRangeTest, RefusedBetweenBeginAndEnd) {
  const GLuint src = MakeBuffer(GL_COPY_READ_BUFFER);
  const GLuint dst = MakeBuffer(GL_COPY_WRITE_BUFFER, 8);
  glBegin(GL_POINTS);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 32, 0, 8);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  const std::vector<unsigned char> bytes = BufferBytes(GL_COPY_WRITE_BUFFER, 8);
  EXPECT_EQ(bytes[0], 0);  // nothing copied
  glBegin(GL_POINTS);
  void* p = glMapBufferRange(GL_COPY_READ_BUFFER, 0, 4, GL_MAP_READ_BIT);
  glEnd();
  EXPECT_EQ(p, nullptr);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(BufferParam(GL_COPY_READ_BUFFER, GL_BUFFER_MAPPED), GL_FALSE);
  ASSERT_NE(glMapBufferRange(GL_COPY_READ_BUFFER, 0, 4, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT), nullptr);
  glBegin(GL_POINTS);
  glFlushMappedBufferRange(GL_COPY_READ_BUFFER, 0, 4);
  glEnd();
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glUnmapBuffer(GL_COPY_READ_BUFFER), GL_TRUE);
  glDeleteBuffers(1, &src);
  glDeleteBuffers(1, &dst);
}

// ---- glCopyBufferSubData ------------------------------------------------------------

TEST_F(BufferRangeTest, CopyBindingPoints) {
  EXPECT_EQ(GetInt(GL_COPY_READ_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_COPY_WRITE_BUFFER_BINDING), 0);
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_COPY_READ_BUFFER, b[0]);
  glBindBuffer(GL_COPY_WRITE_BUFFER, b[1]);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glIsBuffer(b[0]), GL_TRUE);
  EXPECT_EQ(GetInt(GL_COPY_READ_BUFFER_BINDING), static_cast<GLint>(b[0]));
  EXPECT_EQ(GetInt(GL_COPY_WRITE_BUFFER_BINDING), static_cast<GLint>(b[1]));
  EXPECT_EQ(GetFloat(GL_COPY_READ_BUFFER_BINDING), static_cast<GLfloat>(b[0]));
  EXPECT_EQ(GetDouble(GL_COPY_WRITE_BUFFER_BINDING), static_cast<GLdouble>(b[1]));
  EXPECT_EQ(GetBool(GL_COPY_WRITE_BUFFER_BINDING), GL_TRUE);
  // The other buffer commands take the targets too.
  glBufferData(GL_COPY_READ_BUFFER, 8, nullptr, GL_DYNAMIC_COPY);
  EXPECT_EQ(BufferParam(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE), 8);
  EXPECT_EQ(BufferParam(GL_COPY_READ_BUFFER, GL_BUFFER_USAGE), GL_DYNAMIC_COPY);
  EXPECT_NE(glMapBuffer(GL_COPY_READ_BUFFER, GL_READ_ONLY), nullptr);
  EXPECT_EQ(glUnmapBuffer(GL_COPY_READ_BUFFER), GL_TRUE);
  // In no attribute group: glPopClientAttrib leaves them.
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glPopClientAttrib();
  EXPECT_EQ(GetInt(GL_COPY_READ_BUFFER_BINDING), 0);
  glBindBuffer(GL_COPY_READ_BUFFER, b[0]);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glPopAttrib();
  EXPECT_EQ(GetInt(GL_COPY_READ_BUFFER_BINDING), 0);
  // Deleting a bound buffer unbinds it from both.
  glBindBuffer(GL_COPY_READ_BUFFER, b[1]);
  glDeleteBuffers(1, &b[1]);
  EXPECT_EQ(GetInt(GL_COPY_READ_BUFFER_BINDING), 0);
  EXPECT_EQ(GetInt(GL_COPY_WRITE_BUFFER_BINDING), 0);
  EXPECT_NO_GL_ERROR();
  glDeleteBuffers(1, &b[0]);
}

TEST_F(BufferRangeTest, CopiesBetweenEveryPairOfTargets) {
  const GLenum targets[] = {GL_ARRAY_BUFFER,         GL_ELEMENT_ARRAY_BUFFER, GL_PIXEL_PACK_BUFFER,
                            GL_PIXEL_UNPACK_BUFFER, GL_COPY_READ_BUFFER,     GL_COPY_WRITE_BUFFER};
  GLuint b[2];
  glGenBuffers(2, b);
  const unsigned char source[8] = {10, 11, 12, 13, 14, 15, 16, 17};
  for (GLenum from : targets) {
    for (GLenum to : targets) {
      if (from == to) continue;
      SCOPED_TRACE(::testing::Message() << std::hex << from << " -> " << to);
      glBindBuffer(from, b[0]);
      glBufferData(from, 8, source, GL_STREAM_COPY);
      glBindBuffer(to, b[1]);
      glBufferData(to, 8, nullptr, GL_STREAM_COPY);  // zeros
      glCopyBufferSubData(from, to, 1, 2, 4);
      EXPECT_NO_GL_ERROR();
      const std::vector<unsigned char> bytes = BufferBytes(to, 8);
      EXPECT_EQ(bytes, (std::vector<unsigned char>{0, 0, 11, 12, 13, 14, 0, 0}));
      glBindBuffer(from, 0);
      glBindBuffer(to, 0);
    }
  }
  glDeleteBuffers(2, b);
}

// The read buffer (target, then 0 bound), the write buffer, a mapping of
// either (wherever the range), the offsets and size, each range against
// its buffer, then overlap.
TEST_F(BufferRangeTest, CopyErrorsInMesasOrder) {
  const GLuint src = MakeBuffer(GL_COPY_READ_BUFFER, 32);
  const GLuint dst = MakeBuffer(GL_COPY_WRITE_BUFFER, 16);
  const GLenum R = GL_COPY_READ_BUFFER, W = GL_COPY_WRITE_BUFFER;
  const struct {
    GLenum readTarget, writeTarget;
    GLintptr readOffset, writeOffset;
    GLsizeiptr size;
    GLenum error;
  } cases[] = {
      {GL_RGBA, W, -1, 2, 8, GL_INVALID_ENUM},
      {R, GL_RGBA, -1, 2, 8, GL_INVALID_ENUM},
      {GL_PIXEL_PACK_BUFFER, W, -1, 0, 4, GL_INVALID_OPERATION},  // nothing bound
      {W, GL_PIXEL_PACK_BUFFER, -1, 0, 4, GL_INVALID_OPERATION},
      {GL_PIXEL_PACK_BUFFER, GL_RGBA, 0, 0, 4, GL_INVALID_OPERATION},  // the read buffer first
      {GL_RGBA, GL_PIXEL_PACK_BUFFER, 0, 0, 4, GL_INVALID_ENUM},
      {R, W, -1, 2, 8, GL_INVALID_VALUE},
      {R, W, 0, -1, 8, GL_INVALID_VALUE},
      {R, W, 0, 0, -1, GL_INVALID_VALUE},
      {R, W, 30, 0, 4, GL_INVALID_VALUE},
      {R, W, 0, 14, 4, GL_INVALID_VALUE},
      {R, W, 0, 0, 33, GL_INVALID_VALUE},
      {R, W, 33, 16, 0, GL_INVALID_VALUE},  // an empty range past the end
      {R, W, 32, 16, 0, GL_NO_ERROR},       // at the ends
      {R, W, 28, 12, 4, GL_NO_ERROR},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(::testing::Message() << std::hex << c.readTarget << " " << c.writeTarget << std::dec << " "
                                      << c.readOffset << " " << c.writeOffset << " " << c.size);
    glCopyBufferSubData(c.readTarget, c.writeTarget, c.readOffset, c.writeOffset, c.size);
    EXPECT_GL_ERROR(c.error);
  }
  EXPECT_EQ(BufferBytes(W, 16), (std::vector<unsigned char>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 28, 29, 30, 31}));
  // A mapped buffer, even mapped elsewhere, before the offsets.
  ASSERT_NE(glMapBufferRange(W, 0, 2, GL_MAP_WRITE_BIT), nullptr);
  glCopyBufferSubData(R, W, -1, 8, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyBufferSubData(R, W, 0, 8, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glUnmapBuffer(W), GL_TRUE);
  ASSERT_NE(glMapBuffer(R, GL_READ_ONLY), nullptr);
  glCopyBufferSubData(R, W, 0, 8, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  glCopyBufferSubData(W, W, 0, 8, 4);  // neither mapped
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(glUnmapBuffer(R), GL_TRUE);
  glDeleteBuffers(1, &src);
  glDeleteBuffers(1, &dst);
}

// Within one buffer (one binding or two): ranges that touch are fine,
// overlapping ones are GL_INVALID_VALUE, even of one byte at one offset.
TEST_F(BufferRangeTest, CopyWithinOneBuffer) {
  const GLuint b = MakeBuffer(GL_COPY_READ_BUFFER, 32);
  const GLenum R = GL_COPY_READ_BUFFER;
  glCopyBufferSubData(R, R, 0, 4, 8);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyBufferSubData(R, R, 8, 4, 8);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyBufferSubData(R, R, 4, 4, 1);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  glCopyBufferSubData(R, R, 4, 4, 0);
  EXPECT_NO_GL_ERROR();
  glCopyBufferSubData(R, R, 0, 8, 8);  // adjacent
  EXPECT_NO_GL_ERROR();
  glCopyBufferSubData(R, R, 24, 16, 8);  // adjacent, backwards
  EXPECT_NO_GL_ERROR();
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glCopyBufferSubData(GL_ARRAY_BUFFER, R, 0, 2, 4);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);
  const std::vector<unsigned char> bytes = BufferBytes(R, 32);
  const unsigned char expected[32] = {0, 1, 2,  3,  4,  5,  6,  7,  0,  1,  2,  3,  4,  5,  6,  7,
                                      24, 25, 26, 27, 28, 29, 30, 31, 24, 25, 26, 27, 28, 29, 30, 31};
  EXPECT_EQ(bytes, std::vector<unsigned char>(expected, expected + 32));
  glDeleteBuffers(1, &b);
}

// Like the other buffer commands, glCopyBufferSubData runs at once when a
// list is compiled and is not in the list (piglit arb_copy_buffer-dlist).
TEST_F(BufferRangeTest, CopyIsNotCompiledIntoAList) {
  const GLuint src = MakeBuffer(GL_COPY_READ_BUFFER, 8);
  GLuint dst;
  glGenBuffers(1, &dst);
  glBindBuffer(GL_COPY_WRITE_BUFFER, dst);
  glBufferData(GL_COPY_WRITE_BUFFER, 8, nullptr, GL_STATIC_DRAW);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, 8);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, -1, 0, 8);
  EXPECT_GL_ERROR(GL_INVALID_VALUE);  // at once, too
  glEndList();
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferBytes(GL_COPY_WRITE_BUFFER, 8), (std::vector<unsigned char>{0, 1, 2, 3, 4, 5, 6, 7}));
  glBufferData(GL_COPY_WRITE_BUFFER, 8, nullptr, GL_STATIC_DRAW);
  glCallList(list);
  EXPECT_NO_GL_ERROR();
  EXPECT_EQ(BufferBytes(GL_COPY_WRITE_BUFFER, 8), std::vector<unsigned char>(8, 0));
  // So do a mapping and a flush.
  glNewList(list, GL_COMPILE);
  EXPECT_NE(glMapBufferRange(GL_COPY_READ_BUFFER, 0, 4, GL_MAP_READ_BIT), nullptr);
  glFlushMappedBufferRange(GL_COPY_READ_BUFFER, 0, 4);
  EXPECT_GL_ERROR(GL_INVALID_OPERATION);
  EXPECT_EQ(glUnmapBuffer(GL_COPY_READ_BUFFER), GL_TRUE);
  glEndList();
  glDeleteLists(list, 1);
  glDeleteBuffers(1, &src);
  glDeleteBuffers(1, &dst);
}

// ---- drawing ------------------------------------------------------------------------

// Two triangles, x y pairs, and one colour each vertex.
constexpr int kVertexBytes = 6 * 2 * sizeof(GLfloat);
constexpr int kColorBytes = 6 * 4;
void TriangleData(GLfloat* vertices, GLubyte* colors) {
  const GLfloat v[12] = {-0.9f, -0.8f, 0.7f, -0.6f, -0.2f, 0.9f, 0.1f, 0.1f, 0.95f, 0.3f, 0.6f, 0.95f};
  const GLubyte c[24] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                         250, 200, 10, 255, 10, 200, 250, 255, 128, 64, 32, 255};
  std::memcpy(vertices, v, sizeof v);
  std::memcpy(colors, c, sizeof c);
}

// Draws the triangles from the arrays set up, returns glReadPixels' bytes.
std::vector<unsigned char> DrawAndRead(const void* vertices, const void* colors) {
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawArrays(GL_TRIANGLES, 0, 6);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  std::vector<unsigned char> pixels(kWidth * kHeight * 4);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return pixels;
}

// The picture from client arrays, checked to have drawn something.
std::vector<unsigned char> ClientArrayPicture() {
  GLfloat vertices[12];
  GLubyte colors[24];
  TriangleData(vertices, colors);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  std::vector<unsigned char> pixels = DrawAndRead(vertices, colors);
  int drawn = 0;  // pixels unlike the bottom left one, which the triangles miss
  for (size_t i = 0; i < pixels.size(); i += 4) drawn += std::memcmp(&pixels[i], &pixels[0], 4) != 0;
  EXPECT_GT(drawn, 500);
  return pixels;
}

// A VBO filled through two write-only range mappings (the vertices with an
// explicit flush, the colours invalidated) draws what client arrays draw.
TEST_F(BufferRangeTest, DrawFromABufferFilledThroughRanges) {
  const std::vector<unsigned char> expected = ClientArrayPicture();
  GLfloat vertices[12];
  GLubyte colors[24];
  TriangleData(vertices, colors);
  GLuint b;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, 256, nullptr, GL_STREAM_DRAW);
  void* p = glMapBufferRange(GL_ARRAY_BUFFER, 0, kVertexBytes, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
  ASSERT_NE(p, nullptr);
  std::memcpy(p, vertices, kVertexBytes);
  glFlushMappedBufferRange(GL_ARRAY_BUFFER, 0, kVertexBytes);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  p = glMapBufferRange(GL_ARRAY_BUFFER, 128, kColorBytes,
                       GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_UNSYNCHRONIZED_BIT);
  ASSERT_NE(p, nullptr);
  std::memcpy(p, colors, kColorBytes);
  EXPECT_EQ(glUnmapBuffer(GL_ARRAY_BUFFER), GL_TRUE);
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> drawn = DrawAndRead(nullptr, reinterpret_cast<const void*>(128));
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(drawn == expected) << "the range-filled buffer draws other pixels";
  glDeleteBuffers(1, &b);
}

// A VBO whose data came by glCopyBufferSubData, from a copy-read buffer and
// from within itself, draws what client arrays draw.
TEST_F(BufferRangeTest, DrawFromABufferFilledByCopies) {
  const std::vector<unsigned char> expected = ClientArrayPicture();
  GLfloat vertices[12];
  GLubyte colors[24];
  TriangleData(vertices, colors);
  GLuint b[2];
  glGenBuffers(2, b);
  glBindBuffer(GL_COPY_READ_BUFFER, b[0]);
  glBufferData(GL_COPY_READ_BUFFER, kVertexBytes, vertices, GL_STATIC_COPY);
  glBindBuffer(GL_ARRAY_BUFFER, b[1]);
  glBufferData(GL_ARRAY_BUFFER, 256, nullptr, GL_STATIC_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 200, kColorBytes, colors);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_ARRAY_BUFFER, 0, 0, kVertexBytes);
  glCopyBufferSubData(GL_ARRAY_BUFFER, GL_ARRAY_BUFFER, 200, 128, kColorBytes);
  glBufferSubData(GL_ARRAY_BUFFER, 200, kColorBytes, std::vector<unsigned char>(kColorBytes, 0).data());
  EXPECT_NO_GL_ERROR();
  const std::vector<unsigned char> drawn = DrawAndRead(nullptr, reinterpret_cast<const void*>(128));
  EXPECT_NO_GL_ERROR();
  EXPECT_TRUE(drawn == expected) << "the copied buffer draws other pixels";
  glDeleteBuffers(2, b);
}

}  // namespace
