/* Render to texture through a framebuffer object (EXT/ARB_framebuffer_object):
 * a lit torus and sphere, depth-tested against a DEPTH_COMPONENT24
 * renderbuffer, drawn into a 64x64 RGBA8 texture (its own viewport and
 * clear colour), then that texture mapped (GL_MODULATE, linear) on a lit cube
 * turned in the window; the window's depth buffer and viewport come back
 * after glBindFramebuffer(0). */
#include "tex_common.h"

static void inner_scene(void)
{
    glViewport(0, 0, 64, 64);
    glClearColor(0.15f, 0.2f, 0.45f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    light_frustum(0.45f, 1.0f, 1.0f, 20.0f);
    tex_lights();
    glEnable(GL_COLOR_MATERIAL);
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.95f, 0.6f, 0.2f);
    tex_torus(1.2f, 0.4f, 24, 12);
    glColor3f(0.3f, 0.9f, 0.4f);
    tex_sphere(0.7f, 16, 12, 1.0f);
    glDisable(GL_COLOR_MATERIAL);
}

int main(int argc, char **argv)
{
    GLuint fb, depth, tex;
    int f, v;
    scene_begin(argc, argv, 160, 160);

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);

    glGenRenderbuffersEXT(1, &depth);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 64, 64);
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, depth);
    if (glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) != GL_FRAMEBUFFER_COMPLETE_EXT)
        return 1;
    inner_scene();
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);

    glViewport(0, 0, 160, 160);
    scene_clear();
    glEnable(GL_DEPTH_TEST);
    light_frustum(0.3f, 1.0f, 1.0f, 20.0f);
    tex_lights();
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTranslatef(0.0f, 0.0f, -6.0f);
    glRotatef(28.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-37.0f, 0.0f, 1.0f, 0.0f);
    {
        static const float faces[6][5][3] = {
            { { 1, 0, 0 }, { 1, -1, 1 }, { 1, -1, -1 }, { 1, 1, -1 }, { 1, 1, 1 } },
            { { -1, 0, 0 }, { -1, -1, -1 }, { -1, -1, 1 }, { -1, 1, 1 }, { -1, 1, -1 } },
            { { 0, 1, 0 }, { -1, 1, 1 }, { 1, 1, 1 }, { 1, 1, -1 }, { -1, 1, -1 } },
            { { 0, -1, 0 }, { -1, -1, -1 }, { 1, -1, -1 }, { 1, -1, 1 }, { -1, -1, 1 } },
            { { 0, 0, 1 }, { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } },
            { { 0, 0, -1 }, { 1, -1, -1 }, { -1, -1, -1 }, { -1, 1, -1 }, { 1, 1, -1 } },
        };
        static const float st[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
        glBegin(GL_QUADS);
        for (f = 0; f < 6; f++) {
            glNormal3fv(faces[f][0]);
            for (v = 1; v < 5; v++) {
                glTexCoord2fv(st[v - 1]);
                glVertex3fv(faces[f][v]);
            }
        }
        glEnd();
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteFramebuffersEXT(1, &fb);
    glDeleteRenderbuffersEXT(1, &depth);
    glDeleteTextures(1, &tex);
    scene_readpixels_check();
    return scene_end();
}
