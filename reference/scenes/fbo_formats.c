/* Framebuffer objects of GL_RGBA4, GL_RGB5_A1, GL_RGB (5_6_5) and GL_RGBA16
 * textures drawn into, then mapped in the window (fbo_formats_common.h):
 * llvmpipe's conversions to 4, 5, 6 and 16 bits. */
#include "fbo_formats_common.h"

int main(int argc, char **argv)
{
    static const GLenum internal[4] = { GL_RGBA4, GL_RGB5_A1, GL_RGB, GL_RGBA16 };
    static const GLenum format[4] = { GL_RGBA, GL_RGBA, GL_RGB, GL_RGBA };
    static const GLenum type[4] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_BYTE };
    return fbo_formats_scene(argc, argv, internal, format, type);
}
