/* Framebuffer objects of GL_RGB10_A2, GL_RGB10, GL_R3_G3_B2 and
 * GL_LUMINANCE4_ALPHA4 textures drawn into, then mapped in the window
 * (fbo_formats_common.h): llvmpipe's conversions to 10, 3, 2 and 4 bits. */
#include "fbo_formats_common.h"

int main(int argc, char **argv)
{
    static const GLenum internal[4] = { GL_RGB10_A2, GL_RGB10, GL_R3_G3_B2, GL_LUMINANCE4_ALPHA4 };
    static const GLenum format[4] = { GL_RGBA, GL_RGB, GL_RGB, GL_LUMINANCE_ALPHA };
    static const GLenum type[4] = { GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE };
    return fbo_formats_scene(argc, argv, internal, format, type);
}
