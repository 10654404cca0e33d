/* Contour lines by texgen of a 1D stripe texture (GL_REPEAT, GL_LINEAR,
 * GL_MODULATE) on a lit wavy surface:
 *   left:   GL_OBJECT_LINEAR, s = 9 z + 0.5 (lines of equal height);
 *   middle: GL_EYE_LINEAR with the plane given under the identity
 *           modelview (stripes fixed in eye space while the mesh turns);
 *   right:  GL_EYE_LINEAR with the plane given under a rotated and scaled
 *           modelview (the plane is taken through its inverse), and t
 *           generated too, on a GL_TEXTURE_2D stripe grid. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static GLubyte stripes[16 * 4], grid[16 * 16 * 4];
    static const GLfloat obj_plane[4] = { 0.0f, 0.0f, 9.0f, 0.5f };
    static const GLfloat eye_plane[4] = { 2.5f, 1.5f, 0.0f, 0.25f };
    static const GLfloat eye_plane_t[4] = { -1.0f, 3.0f, 0.5f, 0.0f };
    GLuint names[2];
    int i, j, c;
    scene_begin(argc, argv, 384, 128);
    for (i = 0; i < 16; i++)
        tex_put(stripes + 4 * i, i < 2 ? 30 : 200 + 3 * i, i < 2 ? 30 : 220, i < 2 ? 60 : 180 + 4 * i, 255);
    for (j = 0; j < 16; j++)
        for (i = 0; i < 16; i++) {
            int line = i < 2 || j < 2;
            tex_put(grid + 4 * (j * 16 + i), line ? 40 : 240, line ? 60 : 200 + 3 * j, line ? 30 : 170 + 4 * i, 255);
        }
    names[0] = tex_new(GL_TEXTURE_1D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, stripes);
    names[1] = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, grid);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    tex_lights();
    for (c = 0; c < 3; c++) {
        light_cell(c, 3, 1, 128, 128);
        light_frustum(0.42f, 1.0f, 1.0f, 20.0f);
        glEnable(GL_TEXTURE_GEN_S);
        if (c == 0) {
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            glTexGenfv(GL_S, GL_OBJECT_PLANE, obj_plane);
        } else if (c == 1) {
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGenfv(GL_S, GL_EYE_PLANE, eye_plane);
        } else {
            glPushMatrix();
            glRotatef(35.0f, 0.0f, 0.0f, 1.0f);
            glScalef(1.5f, 1.0f, 1.0f);
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
            glTexGenfv(GL_S, GL_EYE_PLANE, eye_plane);
            glTexGenfv(GL_T, GL_EYE_PLANE, eye_plane_t);
            glPopMatrix();
            glEnable(GL_TEXTURE_GEN_T);
        }
        glEnable(c == 2 ? GL_TEXTURE_2D : GL_TEXTURE_1D);
        glTranslatef(0.05f, 0.1f, -3.9f);
        glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(25.0f + 15.0f * c, 0.0f, 0.0f, 1.0f);
        tex_wave_mesh(28, 0);
        glDisable(GL_TEXTURE_1D);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_GEN_T);
    }
    glDeleteTextures(2, names);
    return scene_end();
}
