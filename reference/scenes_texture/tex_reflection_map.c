/* Cube-map environment mapping: texgen GL_REFLECTION_MAP for s, t and r on
 * a lit sphere (left) and torus (middle), GL_NORMAL_MAP on a sphere
 * (right); a cube map whose six faces each have their own colour and a
 * checker, GL_LINEAR, GL_CLAMP_TO_EDGE, GL_MODULATE. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static const GLubyte face_colors[6][3] = { { 230, 80, 70 },  { 80, 200, 90 },  { 90, 110, 230 },
                                               { 230, 210, 80 }, { 200, 90, 210 }, { 80, 210, 220 } };
    static GLubyte img[16 * 16 * 4];
    GLuint name;
    int f, x, y, c;
    scene_begin(argc, argv, 336, 112);
    name = tex_new(GL_TEXTURE_CUBE_MAP, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    for (f = 0; f < 6; f++) {
        for (y = 0; y < 16; y++)
            for (x = 0; x < 16; x++) {
                int on = ((x / 4) ^ (y / 4)) & 1, k = on ? 4 : 2;
                /* a lighter mark in the first texels shows each face's orientation */
                if (x < 3 && y < 2)
                    k = 5;
                tex_put(img + 4 * (y * 16 + x), face_colors[f][0] * k / 5, face_colors[f][1] * k / 5,
                        face_colors[f][2] * k / 5, 255);
            }
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    tex_lights();
    for (c = 0; c < 3; c++) {
        GLenum mode = c == 2 ? GL_NORMAL_MAP : GL_REFLECTION_MAP;
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, mode);
        light_cell(c, 3, 1, 112, 112);
        light_frustum(0.3f, 1.0f, 1.0f, 20.0f);
        glTranslatef(0.0f, 0.0f, -4.0f);
        glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(30.0f + 20.0f * c, 0.0f, 1.0f, 0.0f);
        if (c == 1)
            tex_torus(0.75f, 0.35f, 40, 20);
        else
            tex_sphere(1.0f, 40, 20, 1.0f);
    }
    glDeleteTextures(1, &name);
    return scene_end();
}
