/* Sphere-map environment mapping: texgen GL_SPHERE_MAP for s and t on a lit
 * shiny sphere (left) and torus (right), GL_MODULATE, GL_LINEAR; the
 * environment texture is a sky over ground with a sun and a grid. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static GLubyte env[64 * 64 * 4];
    GLuint name;
    int x, y, c;
    scene_begin(argc, argv, 256, 128);
    for (y = 0; y < 64; y++)
        for (x = 0; x < 64; x++) {
            float u = (x + 0.5f) / 32.0f - 1.0f, v = (y + 0.5f) / 32.0f - 1.0f;
            float sx = u - 0.35f, sy = v - 0.45f;
            GLubyte *p = env + 4 * (y * 64 + x);
            if (sx * sx + sy * sy < 0.03f)
                tex_put(p, 255, 240, 160, 255);
            else if (v > -0.1f)
                tex_put(p, (int)(120 - 80 * v), (int)(170 - 60 * v), 250, 255);
            else
                tex_put(p, 120 + ((x / 8 + y / 8) & 1) * 40, 90, 50, 255);
            if (x % 16 == 0 || y % 16 == 0)
                p[1] = (GLubyte)(p[1] / 2);
        }
    name = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, env);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_2D);
    tex_lights();
    for (c = 0; c < 2; c++) {
        light_cell(c, 2, 1, 128, 128);
        light_frustum(0.3f, 1.0f, 1.0f, 20.0f);
        glTranslatef(0.0f, 0.0f, -4.0f);
        glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
        if (c == 0)
            tex_sphere(1.0f, 40, 20, 1.0f);
        else
            tex_torus(0.75f, 0.35f, 40, 20);
    }
    glDeleteTextures(1, &name);
    return scene_end();
}
