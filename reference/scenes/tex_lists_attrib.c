/* Texture commands in display lists and texture state on the attribute
 * stack, on lit spheres (4 cells):
 *   0: a list binds a texture, loads its image with glTexImage2D and a
 *      glTexSubImage2D patch, sets filters and GL_MODULATE and enables
 *      texturing; the client arrays are overwritten and the texture reloaded
 *      with other data after glEndList, so calling the list shows the image
 *      captured at compile time;
 *   1: glPushAttrib(GL_TEXTURE_BIT | GL_ENABLE_BIT), another binding,
 *      GL_REPLACE and sphere-map texgen for the left sphere, glPopAttrib,
 *      then the right sphere with the restored state;
 *   2: a list that loads the texture matrix (translate, rotate, scale);
 *   3: GL_COMPILE_AND_EXECUTE of object-linear texgen and a wavy mesh,
 *      then the list called again under another modelview. */
#include "tex_common.h"

int main(int argc, char **argv)
{
    static GLubyte img[16 * 16 * 4], patch[4 * 4 * 4], other[16 * 16 * 4];
    static const GLubyte c0[4] = { 240, 200, 80, 255 }, c1[4] = { 60, 120, 200, 255 };
    static const GLubyte d0[4] = { 90, 220, 120, 255 }, d1[4] = { 200, 60, 160, 255 };
    static const GLfloat plane_s[4] = { 2.0f, 0.0f, 0.0f, 0.0f }, plane_t[4] = { 0.0f, 2.0f, 1.0f, 0.0f };
    GLuint t[2], lists;
    int i;
    scene_begin(argc, argv, 384, 96);
    tex_checker(img, 16, 16, 4, c0, c1);
    tex_checker(other, 16, 16, 2, d0, d1);
    for (i = 0; i < 16; i++)
        tex_put(patch + 4 * i, 250, 250, 250, 255);
    glGenTextures(2, t);
    lists = glGenLists(3);

    glNewList(lists, GL_COMPILE);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 6, 6, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, patch);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glEndList();
    /* after compiling: other client data, other texture contents */
    memcpy(img, other, sizeof img);
    memset(patch, 0, sizeof patch);
    glBindTexture(GL_TEXTURE_2D, t[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, other);

    glBindTexture(GL_TEXTURE_2D, t[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, other);

    glNewList(lists + 1, GL_COMPILE);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.3f, 0.1f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glScalef(2.0f, 1.5f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glEndList();

    tex_lights();
    for (i = 0; i < 4; i++) {
        light_cell(i, 4, 1, 96, 96);
        light_ortho(1.05f, 1.0f);
        glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
        switch (i) {
        case 0:
            glCallList(lists);
            tex_sphere(1.0f, 32, 16, 2.0f);
            break;
        case 1:
            glPushAttrib(GL_TEXTURE_BIT | GL_ENABLE_BIT);
            glBindTexture(GL_TEXTURE_2D, t[1]);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
            glPushMatrix();
            glTranslatef(-0.5f, 0.0f, 0.0f);
            tex_sphere(0.48f, 24, 12, 2.0f);
            glPopMatrix();
            glPopAttrib();
            glTranslatef(0.5f, 0.0f, 0.0f);
            tex_sphere(0.48f, 24, 12, 2.0f);
            break;
        case 2:
            glCallList(lists + 1);
            tex_sphere(1.0f, 32, 16, 2.0f);
            glMatrixMode(GL_TEXTURE);
            glLoadIdentity();
            glMatrixMode(GL_MODELVIEW);
            break;
        case 3:
            glRotatef(-40.0f, 1.0f, 0.0f, 0.0f);
            glPushMatrix();
            glTranslatef(0.0f, 0.35f, 0.0f);
            glScalef(0.9f, 0.45f, 0.9f);
            glNewList(lists + 2, GL_COMPILE_AND_EXECUTE);
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            glTexGenfv(GL_S, GL_OBJECT_PLANE, plane_s);
            glTexGenfv(GL_T, GL_OBJECT_PLANE, plane_t);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
            tex_wave_mesh(12, 0);
            glDisable(GL_TEXTURE_GEN_S);
            glDisable(GL_TEXTURE_GEN_T);
            glEndList();
            glPopMatrix();
            glTranslatef(0.0f, -0.5f, 0.0f);
            glScalef(0.9f, 0.45f, 0.9f);
            glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
            glCallList(lists + 2);
            break;
        }
    }
    glDeleteLists(lists, 3);
    glDeleteTextures(2, t);
    return scene_end();
}
