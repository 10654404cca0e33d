/* Mipmaps made by GL on the receding checkerboard floor
 * (GL_LINEAR_MIPMAP_LINEAR): left GL_GENERATE_MIPMAP set before
 * glTexImage2D, then a glTexSubImage2D patch (which regenerates the
 * levels); middle glGenerateMipmap after glTexImage2D; right
 * glGenerateMipmap of a non-power-of-two 48x40 base level (Mesa's filter
 * for odd sizes decides the smaller levels). */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static GLubyte img[64 * 64 * 4], npot[48 * 40 * 4], patch[16 * 16 * 4];
    GLuint names[3];
    int i, x, y;
    scene_begin(argc, argv, 300, 80);
    tex_floor_image(img);
    for (i = 0; i < 16 * 16; i++)
        tex_put(patch + 4 * i, 40, 160 + i % 16 * 5, 60, 255);
    for (y = 0; y < 40; y++)
        for (x = 0; x < 48; x++) {
            int on = ((x / 6) ^ (y / 5)) & 1;
            tex_put(npot + 4 * (y * 48 + x), on ? 240 : 30, on ? 230 : 90, on ? 120 : 170, 255);
        }
    names[0] = tex_new(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, patch);
    tex_floor_view(0, 0, 100, 80);
    names[1] = tex_new(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glGenerateMipmap(GL_TEXTURE_2D);
    tex_floor_view(100, 0, 100, 80);
    names[2] = tex_new(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 48, 40, 0, GL_RGBA, GL_UNSIGNED_BYTE, npot);
    glGenerateMipmap(GL_TEXTURE_2D);
    tex_floor_view(200, 0, 100, 80);
    glDeleteTextures(3, names);
    return scene_end();
}
