/* The drawing of the fbo_formats scenes: a lit, depth-tested torus and
 * sphere drawn with a blended translucent quad over them into four 64x64
 * textures of the given formats (sharing one DEPTH_COMPONENT24
 * renderbuffer), then the four textures mapped (GL_REPLACE, nearest) on quads
 * in the window's four corners. The texels are what llvmpipe's conversions
 * to each format's bits made of the fragments' colours and the blend. */
#include "tex_common.h"

static inline void fbo_formats_inner_scene(int i)
{
    glViewport(0, 0, 64, 64);
    glClearColor(0.15f + 0.1f * i, 0.2f, 0.45f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    light_frustum(0.45f, 1.0f, 1.0f, 20.0f);
    tex_lights();
    glEnable(GL_COLOR_MATERIAL);
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(35.0f + 10.0f * i, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.95f, 0.6f, 0.2f);
    tex_torus(1.2f, 0.4f, 24, 12);
    glColor3f(0.3f, 0.9f, 0.4f);
    tex_sphere(0.7f, 16, 12, 1.0f);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.1f, 0.6f, 0.2f);
    glVertex2f(-0.8f, -0.8f);
    glColor4f(0.2f, 0.9f, 1.0f, 0.7f);
    glVertex2f(0.7f, -0.6f);
    glColor4f(0.9f, 0.9f, 0.1f, 0.5f);
    glVertex2f(0.6f, 0.2f);
    glColor4f(0.1f, 0.3f, 0.9f, 0.9f);
    glVertex2f(-0.7f, 0.1f);
    glEnd();
    glDisable(GL_BLEND);
}

static inline int fbo_formats_scene(int argc, char **argv, const GLenum internal[4], const GLenum format[4],
                                    const GLenum type[4])
{
    GLuint fb, depth, tex[4];
    int i;
    scene_begin(argc, argv, 160, 160);

    glGenTextures(4, tex);
    glGenRenderbuffersEXT(1, &depth);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, depth);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 64, 64);
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, depth);
    for (i = 0; i < 4; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, internal[i], 64, 64, 0, format[i], type[i], NULL);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex[i], 0);
        if (glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) != GL_FRAMEBUFFER_COMPLETE_EXT)
            return 1;
        fbo_formats_inner_scene(i);
    }
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);

    glViewport(0, 0, 160, 160);
    scene_clear();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (i = 0; i < 4; i++) {
        float x0 = (i & 1) ? 0.05f : -0.95f, y0 = (i & 2) ? 0.05f : -0.95f;
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0);
        glVertex2f(x0, y0);
        glTexCoord2f(1, 0);
        glVertex2f(x0 + 0.8f, y0);
        glTexCoord2f(1, 1);
        glVertex2f(x0 + 0.8f, y0 + 0.8f);
        glTexCoord2f(0, 1);
        glVertex2f(x0, y0 + 0.8f);
        glEnd();
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteFramebuffersEXT(1, &fb);
    glDeleteRenderbuffersEXT(1, &depth);
    glDeleteTextures(4, tex);
    scene_readpixels_check();
    return scene_end();
}
