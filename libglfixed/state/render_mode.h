// The render mode and what GL_SELECT and GL_FEEDBACK write (GL 2.1 §5.2,
// §5.3). None of it is in a glPushAttrib group; the name stack is a client of
// GL_SELECT only.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

namespace glfixed {

constexpr int kMaxNameStackDepth = 64;  // Mesa's MAX_NAME_STACK_DEPTH

struct SelectState {
  GLuint* buffer = nullptr;  // the application's, from glSelectBuffer
  GLsizei bufferSize = 0;    // > 0 only with a buffer
  bool bufferGiven = false;  // glSelectBuffer was called (§5.2)
  size_t bufferCount = 0;    // words written or that would have been (overflow)
  GLuint hits = 0;
  // A primitive reached the selection stage since the last hit record; the
  // window z range it covered (GL 2.1 §5.2).
  bool hitFlag = false;
  float hitMinZ = 1.0f, hitMaxZ = 0.0f;
  GLuint nameStack[kMaxNameStackDepth] = {};
  int nameStackDepth = 0;

  // One word into the buffer; past its end only counted (the overflow
  // glRenderMode reports).
  void write(GLuint value) {
    if (bufferCount < static_cast<size_t>(bufferSize)) buffer[bufferCount] = value;
    ++bufferCount;
  }
  void updateHitFlag(float z) {
    hitFlag = true;
    if (z < hitMinZ) hitMinZ = z;
    if (z > hitMaxZ) hitMaxZ = z;
  }
  void resetHit() {
    hitFlag = false;
    hitMinZ = 1.0f;
    hitMaxZ = 0.0f;
  }
  void writeHitRecord();
};

struct FeedbackState {
  GLfloat* buffer = nullptr;  // the application's, from glFeedbackBuffer
  GLsizei bufferSize = 0;     // > 0 only with a buffer
  bool bufferGiven = false;   // glFeedbackBuffer was called (§5.3)
  GLenum type = GL_2D;
  size_t count = 0;  // values written or that would have been (overflow)

  void token(GLfloat value) {
    if (count < static_cast<size_t>(bufferSize)) buffer[count] = value;
    ++count;
  }
};

struct RenderModeState {
  GLenum mode = GL_RENDER;
  SelectState select;
  FeedbackState feedback;
};

}  // namespace glfixed
