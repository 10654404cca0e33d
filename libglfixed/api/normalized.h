// Integer to float conversion of vertex attributes, GL 2.1 table 2.9,
// evaluated as Mesa does (a multiply by the reciprocal, in single precision):
// signed c maps to (2c + 1) / (2^b - 1), unsigned c to c / (2^b - 1).
#pragma once

#include <GL/gl.h>

namespace glfixed::api {

inline float normalized(GLbyte c) { return (2.0f * c + 1.0f) * (1.0f / 255.0f); }
inline float normalized(GLshort c) { return (2.0f * c + 1.0f) * (1.0f / 65535.0f); }
inline float normalized(GLint c) { return static_cast<float>((2.0f * c + 1.0f) * (1.0 / 4294967294.0)); }
inline float normalized(GLubyte c) { return static_cast<float>(c) / 255.0f; }
inline float normalized(GLushort c) { return static_cast<float>(c) * (1.0f / 65535.0f); }
inline float normalized(GLuint c) { return static_cast<float>(c * (1.0 / 4294967295.0)); }
inline float normalized(GLfloat c) { return c; }
inline float normalized(GLdouble c) { return static_cast<float>(c); }

}  // namespace glfixed::api
