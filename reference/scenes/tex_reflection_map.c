/* Cube-map environment mapping: texgen GL_REFLECTION_MAP for s, t and r on
 * a lit sphere (left) and torus (middle), GL_NORMAL_MAP on a sphere
 * (right); a cube map whose six faces each have their own colour and a
 * checker (tex_cube_map_faces), GL_LINEAR, GL_CLAMP_TO_EDGE, GL_MODULATE. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    GLuint name;
    int c;
    scene_begin(argc, argv, 336, 112);
    name = tex_new(GL_TEXTURE_CUBE_MAP, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    tex_cube_map_faces(16);
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
