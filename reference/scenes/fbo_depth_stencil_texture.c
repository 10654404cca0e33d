/* A depth-stencil texture (EXT_packed_depth_stencil, GL_DEPTH24_STENCIL8) as
 * a framebuffer object's depth and stencil attachment: a stencil mask (a
 * ring of wedges, colour writes off) is drawn into it, then a lit torus and
 * sphere, depth-tested, only where the mask is set. Back in the window the
 * texture is sampled as a depth texture: on the left as luminance
 * (GL_DEPTH_TEXTURE_MODE), on the right compared (GL_TEXTURE_COMPARE_MODE,
 * GL_LEQUAL, linear: the four compares weighted) against an r that runs
 * across the quad, as alpha blended over a lit backdrop. The inner scene is
 * orthographic: its depth is linear in z. */
#include "tex_common.h"

#include <math.h>

#ifndef GL_DEPTH_STENCIL_EXT
#define GL_DEPTH_STENCIL_EXT 0x84F9
#endif
#ifndef GL_UNSIGNED_INT_24_8_EXT
#define GL_UNSIGNED_INT_24_8_EXT 0x84FA
#endif
#ifndef GL_DEPTH24_STENCIL8_EXT
#define GL_DEPTH24_STENCIL8_EXT 0x88F0
#endif

static void stencil_mask(void)
{
    int i;
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 9; i++) {
        const float a0 = (float)i * 6.2831853f / 9.0f, a1 = a0 + 0.45f;
        glVertex2f(0.0f, 0.0f);
        glVertex2f(1.6f * cosf(a0), 1.6f * sinf(a0));
        glVertex2f(1.6f * cosf(a1), 1.6f * sinf(a1));
    }
    glEnd();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
}

static void inner_scene(void)
{
    glViewport(0, 0, 64, 64);
    glClearColor(0.1f, 0.1f, 0.3f, 1.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.6, 1.6, -1.6, 1.6, 2.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -5.0f);
    stencil_mask();
    glPopMatrix();
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_DEPTH_TEST);
    tex_lights();
    glEnable(GL_COLOR_MATERIAL);
    glTranslatef(0.0f, 0.0f, -5.0f);
    glRotatef(50.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.95f, 0.6f, 0.2f);
    tex_torus(1.1f, 0.35f, 24, 12);
    glColor3f(0.3f, 0.9f, 0.4f);
    tex_sphere(0.65f, 16, 12, 1.0f);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_LIGHTING);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
}

static void quad(float x0, float x1, float r0, float r1)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r0);
    glVertex2f(x0, -0.8f);
    glTexCoord3f(1, 0, r1);
    glVertex2f(x1, -0.8f);
    glTexCoord3f(1, 1, r1);
    glVertex2f(x1, 0.8f);
    glTexCoord3f(0, 1, r0);
    glVertex2f(x0, 0.8f);
    glEnd();
}

int main(int argc, char **argv)
{
    GLuint fb, color, ds;
    scene_set_stencil_bits(8);
    scene_begin(argc, argv, 160, 96);

    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGenTextures(1, &ds);
    glBindTexture(GL_TEXTURE_2D, ds);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8_EXT, 64, 64, 0, GL_DEPTH_STENCIL_EXT,
                 GL_UNSIGNED_INT_24_8_EXT, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);

    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, color, 0);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_TEXTURE_2D, ds, 0);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_STENCIL_ATTACHMENT_EXT, GL_TEXTURE_2D, ds, 0);
    if (glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) != GL_FRAMEBUFFER_COMPLETE_EXT)
        return 1;
    inner_scene();
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);

    glViewport(0, 0, 160, 96);
    scene_clear();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.7, 1.7, -1.0, 1.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* A lit backdrop for the right quad's compared alpha to blend over. */
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.2f, 0.2f);
    glVertex2f(0.05f, -0.9f);
    glColor3f(0.2f, 0.9f, 0.2f);
    glVertex2f(1.65f, -0.9f);
    glColor3f(0.2f, 0.2f, 0.9f);
    glVertex2f(1.65f, 0.9f);
    glColor3f(0.9f, 0.9f, 0.2f);
    glVertex2f(0.05f, 0.9f);
    glEnd();

    glBindTexture(GL_TEXTURE_2D, ds);
    glEnable(GL_TEXTURE_2D);
    glColor3f(1.0f, 1.0f, 1.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    quad(-1.65f, -0.05f, 0.0f, 0.0f);

    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    quad(0.05f, 1.65f, 0.35f, 0.75f);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);

    glDeleteFramebuffersEXT(1, &fb);
    glDeleteTextures(1, &color);
    glDeleteTextures(1, &ds);
    scene_readpixels_check();
    return scene_end();
}
