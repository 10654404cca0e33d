/* Level-of-detail controls on the receding checkerboard floor
 * (GL_LINEAR_MIPMAP_LINEAR, every level uploaded and tinted so the level
 * shows), 3x2 cells:
 *   0: GL_TEXTURE_LOD_BIAS +1.5 in the texture environment
 *      (GL_TEXTURE_FILTER_CONTROL);
 *   1: GL_TEXTURE_LOD_BIAS -1.0 on the texture object;
 *   2: GL_TEXTURE_MIN_LOD 1.5, GL_TEXTURE_MAX_LOD 3.2;
 *   3: GL_TEXTURE_BASE_LEVEL 1, GL_TEXTURE_MAX_LEVEL 3;
 *   4: GL_TEXTURE_BASE_LEVEL 2 (magnification samples the base level);
 *   5: environment bias -0.7 plus object bias +0.4, GL_TEXTURE_MAX_LOD 2. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static GLubyte img[64 * 64 * 4];
    GLuint names[6];
    int c;
    scene_begin(argc, argv, 300, 150);
    tex_floor_image(img);
    for (c = 0; c < 6; c++) {
        names[c] = tex_new(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
        tex_upload_mipmaps(img, 64, 64, GL_RGBA);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
        switch (c) {
        case 0: glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f); break;
        case 1: glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -1.0f); break;
        case 2:
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.5f);
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.2f);
            break;
        case 3:
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
            break;
        case 4: glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2); break;
        case 5:
            glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -0.7f);
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.4f);
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.0f);
            break;
        }
        tex_floor_view(c % 3 * 100, (1 - c / 3) * 75, 100, 75);
    }
    glDeleteTextures(6, names);
    return scene_end();
}
