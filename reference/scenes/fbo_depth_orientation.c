/* Framebuffer objects are rasterized with y up: Mesa's state tracker flips y
 * for window-system buffers only, so into an object llvmpipe snaps, applies
 * its fill rule and rounds interpolants in GL's own rows. Two 64x64 objects,
 * each with a DEPTH_COMPONENT24 renderbuffer: one RGBA8, one RGBA32F. Into
 * each: a lit, culled torus and two tilted triangles in perspective (depth
 * tested), triangles with edges exactly on pixel centres, lines, points of
 * several sizes, point sprites with both coordinate origins, a stippled
 * polygon, a glBitmap and a zoomed glDrawPixels; into a third RGBA8 one smooth
 * lines and points, a scissored triangle, polygon offset, two-sided lighting,
 * glCopyPixels and a depth glDrawPixels; into a fourth polygon modes, line
 * stipple, textured bitmaps, negative pixel zooms and a scissored wide point.
 * Their colour (bytes, or the
 * float bits) and depth (GL_UNSIGNED_INT, the 24 bits as RGB bytes) are read
 * back and drawn into the window side by side with glDrawPixels, where the
 * harness compares them: every byte must equal Mesa's. */
#include <string.h>

#include "tex_common.h"

enum { N = 64 };

static void perspective_part(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    tex_lights();
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_CULL_FACE);
    glPushMatrix();
    glTranslatef(-0.3f, 0.25f, -5.0f);
    glRotatef(55.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.95f, 0.6f, 0.2f);
    tex_torus(1.1f, 0.35f, 20, 10);
    glPopMatrix();
    glDisable(GL_CULL_FACE);
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    /* Two tilted perspective triangles crossing each other. */
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.2f, 0.3f);
    glVertex3f(-1.5f, -1.3f, -2.5f);
    glColor3f(0.2f, 0.9f, 0.3f);
    glVertex3f(0.6f, -1.1f, -6.5f);
    glColor3f(0.2f, 0.3f, 0.9f);
    glVertex3f(-0.2f, 0.4f, -3.3f);
    glColor3f(0.8f, 0.8f, 0.1f);
    glVertex3f(1.4f, -1.5f, -3.1f);
    glColor3f(0.1f, 0.8f, 0.8f);
    glVertex3f(1.0f, 0.9f, -7.0f);
    glColor3f(0.8f, 0.1f, 0.8f);
    glVertex3f(-0.9f, -0.2f, -4.4f);
    glEnd();
}

static void pixel_part(GLuint sprite_tex)
{
    static const GLubyte bitmap[8] = { 0x81, 0x42, 0x24, 0x18, 0x18, 0x24, 0x42, 0xff };
    GLubyte image[6 * 5 * 4];
    int i, j;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, N, 0.0, N, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* Edges exactly on pixel centres: horizontal bottom and top edges, a
     * vertical edge, shared edges of a fan (GL's fill rule, bottom-left). */
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.5f, 0.0f);
    glVertex3f(2.5f, 2.5f, 0.2f);
    glVertex3f(12.5f, 2.5f, -0.1f);
    glVertex3f(7.5f, 9.5f, 0.3f);
    glColor3f(0.0f, 0.6f, 1.0f);
    glVertex3f(2.5f, 9.5f, 0.1f);
    glVertex3f(7.5f, 9.5f, 0.1f);   /* top edge on a centre row, shared */
    glVertex3f(4.5f, 14.5f, -0.2f);
    glColor3f(0.6f, 1.0f, 0.2f);
    glVertex3f(14.5f, 2.5f, 0.0f);
    glVertex3f(14.5f, 12.5f, 0.5f);  /* vertical edge on a centre column */
    glVertex3f(20.5f, 7.5f, -0.4f);
    glEnd();
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.9f, 0.9f);
    glVertex2f(22.5f, 2.5f);
    glVertex2f(30.5f, 2.5f);
    glVertex2f(30.5f, 6.5f);
    glVertex2f(22.5f, 6.5f);
    glEnd();
    /* Lines: horizontal and vertical on centres, diagonals, wide ones. */
    glBegin(GL_LINES);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(33.5f, 2.5f);
    glVertex2f(45.5f, 2.5f);
    glVertex2f(33.5f, 4.0f);
    glVertex2f(45.5f, 4.0f);
    glVertex2f(47.5f, 2.5f);
    glVertex2f(47.5f, 14.5f);
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex2f(33.0f, 6.0f);
    glVertex2f(45.0f, 14.0f);
    glVertex2f(33.5f, 14.5f);
    glVertex2f(44.5f, 7.5f);
    glVertex3f(50.2f, 3.3f, -0.5f);
    glVertex3f(62.7f, 13.1f, 0.5f);
    glEnd();
    glLineWidth(3.0f);
    glBegin(GL_LINE_STRIP);
    glColor3f(1.0f, 0.3f, 0.6f);
    glVertex2f(50.5f, 16.5f);
    glVertex2f(62.5f, 16.5f);
    glVertex2f(56.0f, 22.0f);
    glEnd();
    glLineWidth(1.0f);
    /* Points of sizes 1 to 4, on centres and on edges between pixels. */
    for (i = 1; i <= 4; i++) {
        glPointSize((float)i);
        glBegin(GL_POINTS);
        glColor3f(0.3f * i, 1.0f - 0.2f * i, 0.5f);
        glVertex2f(4.5f + 8.0f * i, 20.5f);
        glVertex2f(5.0f + 8.0f * i, 26.0f);
        glVertex3f(4.25f + 8.0f * i, 31.75f, 0.3f);
        glEnd();
    }
    /* Point sprites: the coordinate origin is window-relative. */
    glBindTexture(GL_TEXTURE_2D, sprite_tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glPointSize(8.0f);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glBegin(GL_POINTS);
    glVertex2f(44.0f, 28.0f);
    glVertex2f(54.3f, 27.6f);
    glEnd();
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    glBegin(GL_POINTS);
    glVertex2f(44.0f, 38.0f);
    glVertex2f(54.5f, 38.5f);
    glEnd();
    glDisable(GL_POINT_SPRITE);
    glDisable(GL_TEXTURE_2D);
    glPointSize(1.0f);
    /* A stippled polygon: the pattern is window-relative. */
    {
        GLubyte pattern[128];
        for (i = 0; i < 128; i++)
            pattern[i] = (GLubyte)((i / 4) % 3 == 0 ? 0xf0 : (i % 5 == 0 ? 0x3c : 0x81));
        glPolygonStipple(pattern);
        glEnable(GL_POLYGON_STIPPLE);
        glBegin(GL_TRIANGLES);
        glColor3f(0.7f, 0.2f, 1.0f);
        glVertex2f(3.0f, 36.0f);
        glVertex2f(30.0f, 38.0f);
        glVertex2f(12.0f, 60.0f);
        glEnd();
        glDisable(GL_POLYGON_STIPPLE);
    }
    /* glBitmap and a zoomed glDrawPixels. */
    glColor3f(1.0f, 1.0f, 1.0f);
    glRasterPos3f(33.0f, 44.0f, 0.2f);
    glBitmap(8, 8, 0.0f, 0.0f, 10.0f, 1.0f, bitmap);
    glBitmap(8, 8, 0.0f, 0.0f, 10.0f, 1.0f, bitmap);
    for (j = 0; j < 5; j++)
        for (i = 0; i < 6; i++)
            tex_put(&image[(j * 6 + i) * 4], 40 * i, 50 * j, 255 - 30 * i - 20 * j, 255);
    glRasterPos2i(34, 53);
    glPixelZoom(1.5f, 1.75f);
    glDrawPixels(6, 5, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glPixelZoom(1.0f, 1.0f);
}

/* The rest, into a third object: smooth (blended) lines and points, a
 * scissored draw, polygon offset, two-sided lighting, glCopyPixels (the blit
 * path and a zoomed one) and a depth glDrawPixels. */
static void extra_part(void)
{
    GLfloat depth_image[8 * 6];
    int i;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.3f, 0.8f, 0.5f);
    glBegin(GL_QUADS);  /* seen from behind at the top: the back material */
    glNormal3f(0.0f, 0.3f, 1.0f);
    glVertex3f(-1.4f, 0.3f, -3.0f);
    glVertex3f(-1.2f, 1.3f, -4.5f);
    glVertex3f(1.3f, 1.2f, -5.0f);
    glVertex3f(1.1f, 0.2f, -3.3f);
    glEnd();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 3.0f);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.4f, 0.1f);
    glVertex3f(-1.0f, -0.2f, -2.8f);
    glColor3f(0.1f, 0.4f, 0.9f);
    glVertex3f(0.9f, 0.1f, -6.0f);
    glColor3f(0.5f, 0.9f, 0.4f);
    glVertex3f(0.0f, 1.0f, -3.9f);
    glEnd();
    glDisable(GL_POLYGON_OFFSET_FILL);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, N, 0.0, N, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 1.0f, 0.6f);
    glVertex2f(2.3f, 3.1f);
    glVertex2f(30.6f, 17.4f);
    glVertex2f(3.5f, 20.5f);
    glVertex2f(28.5f, 20.5f);
    glEnd();
    glDisable(GL_LINE_SMOOTH);
    glLineWidth(1.0f);
    glEnable(GL_POINT_SMOOTH);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    glColor3f(0.4f, 1.0f, 1.0f);
    glVertex2f(36.3f, 6.6f);
    glVertex2f(44.5f, 6.5f);
    glVertex2f(52.0f, 7.0f);
    glEnd();
    glDisable(GL_POINT_SMOOTH);
    glPointSize(1.0f);
    glDisable(GL_BLEND);
    /* Scissored: only [34, 60) x [12, 30) of the triangle. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(34, 12, 26, 18);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.6f);
    glVertex2f(30.0f, 10.0f);
    glColor3f(0.2f, 0.2f, 1.0f);
    glVertex2f(63.0f, 14.0f);
    glColor3f(1.0f, 1.0f, 0.2f);
    glVertex2f(45.0f, 33.0f);
    glEnd();
    glDisable(GL_SCISSOR_TEST);
    /* glCopyPixels within the object, as it is and zoomed. */
    glDisable(GL_DEPTH_TEST);
    glRasterPos2i(2, 34);
    glCopyPixels(36, 12, 14, 10, GL_COLOR);
    glRasterPos2i(18, 34);
    glPixelZoom(1.5f, 2.0f);
    glCopyPixels(0, 0, 10, 12, GL_COLOR);
    glPixelZoom(1.0f, 1.0f);
    /* A depth image drawn with GL_ALWAYS. */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    for (i = 0; i < 8 * 6; i++)
        depth_image[i] = 0.1f + 0.015f * (float)i;
    glColor3f(0.6f, 0.6f, 0.6f);
    glRasterPos3f(44.0f, 40.0f, 0.0f);
    glPixelZoom(2.0f, 1.5f);
    glDrawPixels(8, 6, GL_DEPTH_COMPONENT, GL_FLOAT, depth_image);
    glPixelZoom(1.0f, 1.0f);
    glDepthFunc(GL_LESS);
}

/* A fourth object: glPolygonMode lines and points (front and back),
 * stippled lines, a textured glBitmap, glDrawPixels and glCopyPixels with
 * negative zooms, and a selection of the object's rows by the scissor. */
static void more_part(GLuint sprite_tex)
{
    static const GLubyte bitmap[16] = { 0xff, 0x80, 0xc1, 0x80, 0xa2, 0x80, 0x94, 0x80,
                                        0x88, 0x80, 0x94, 0x80, 0xa2, 0x80, 0xff, 0x80 };
    GLubyte image[5 * 4 * 4];
    int i;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, N, 0.0, N, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.6f, 0.2f);
    glVertex2f(3.5f, 3.5f);
    glVertex2f(25.5f, 6.5f);
    glVertex2f(10.5f, 24.5f);
    glColor3f(0.2f, 0.9f, 1.0f);
    glVertex2f(30.5f, 4.5f);
    glVertex2f(38.0f, 24.0f);
    glVertex2f(58.5f, 8.5f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x33f1);
    glBegin(GL_LINE_STRIP);
    glColor3f(0.9f, 0.9f, 0.3f);
    glVertex2f(2.5f, 30.5f);
    glVertex2f(60.5f, 28.5f);
    glVertex2f(40.5f, 40.0f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    /* A textured bitmap: the current texture coordinates, the sprite texture. */
    glBindTexture(GL_TEXTURE_2D, sprite_tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor3f(1.0f, 1.0f, 1.0f);
    glTexCoord2f(0.3f, 0.8f);
    glRasterPos2i(4, 44);
    glBitmap(9, 8, 0.0f, 0.0f, 12.0f, 0.0f, bitmap);
    glTexCoord2f(0.9f, 0.1f);
    glRasterPos2i(16, 44);
    glBitmap(9, 8, 0.0f, 0.0f, 12.0f, 0.0f, bitmap);
    /* Drawn now: Mesa 22.3.6 crashes flushing its bitmap cache after the
     * texture is disabled and unbound (MESA_FACTS.md "Pixel rectangles"). */
    glFlush();
    glDisable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    /* Negative zooms. */
    for (i = 0; i < 20; i++)
        tex_put(&image[i * 4], 60 * (i % 5), 80 * (i / 5), 200 - 9 * i, 255);
    glDisable(GL_DEPTH_TEST);
    glRasterPos2i(40, 60);
    glPixelZoom(1.5f, -2.0f);
    glDrawPixels(5, 4, GL_RGBA, GL_UNSIGNED_BYTE, image);
    glRasterPos2i(62, 42);
    glPixelZoom(-1.0f, 1.5f);
    glCopyPixels(30, 4, 12, 8, GL_COLOR);
    glPixelZoom(1.0f, 1.0f);
    /* The scissor box cuts a wide point and a triangle. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(30, 50, 9, 7);
    glPointSize(12.0f);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 0.3f, 0.3f);
    glVertex2f(32.0f, 52.0f);
    glEnd();
    glPointSize(1.0f);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
}

/* Renders the scene into a new 64x64 object of colour `format` and reads it
 * back: the colour as `type` into `color`, the depth as GL_UNSIGNED_INT. */
static void render_object(GLenum format, GLenum type, void *color, GLuint *depth_values, GLuint sprite_tex,
                          int extra)
{
    GLuint fb, rb[2];
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, format, N, N);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, N, N);
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
        glViewport(0, 0, N, N);
        glClearColor(0.1f, 0.15f, 0.3f, 1.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        if (extra == 2) {
            more_part(sprite_tex);
        } else if (extra) {
            extra_part();
        } else {
            perspective_part();
            pixel_part(sprite_tex);
        }
        glDisable(GL_DEPTH_TEST);
        glReadPixels(0, 0, N, N, GL_RGBA, type, color);
        glReadPixels(0, 0, N, N, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth_values);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(2, rb);
}

/* The 24 depth bits of each value as R, G, B bytes (alpha 255). */
static void depth_as_bytes(const GLuint *depth_values, GLubyte *out)
{
    int i;
    for (i = 0; i < N * N; i++) {
        GLuint d = depth_values[i] >> 8;
        tex_put(&out[i * 4], (int)(d >> 16) & 255, (int)(d >> 8) & 255, (int)d & 255, 255);
    }
}

static void put_image(int x, int w, const void *pixels)
{
    glWindowPos2i(x, 0);
    glDrawPixels(w, N, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
}

int main(int argc, char **argv)
{
    static GLubyte bytes[N * N * 4], depth_bytes[N * N * 4];
    static GLfloat floats[N * N * 4];
    static GLuint depth_values[N * N];
    GLubyte sprite[4 * 4 * 4];
    GLuint sprite_tex;
    int i;
    scene_begin(argc, argv, 10 * N, N);
    sprite_tex = tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    for (i = 0; i < 16; i++)
        tex_put(&sprite[i * 4], (i % 4) * 80, (i / 4) * 80, ((i + i / 4) & 1) ? 255 : 40, 255);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, sprite);
    glBindTexture(GL_TEXTURE_2D, 0);

    render_object(GL_RGBA8, GL_UNSIGNED_BYTE, bytes, depth_values, sprite_tex, 0);
    depth_as_bytes(depth_values, depth_bytes);
    glViewport(0, 0, 10 * N, N);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    put_image(0, N, bytes);
    put_image(N, N, depth_bytes);

    render_object(GL_RGBA32F, GL_FLOAT, floats, depth_values, sprite_tex, 0);
    depth_as_bytes(depth_values, depth_bytes);
    /* Each float pixel's 16 bytes as 4 window pixels: 4N bytes-pixels a row. */
    glViewport(0, 0, 10 * N, N);
    put_image(2 * N, 4 * N, floats);
    put_image(6 * N, N, depth_bytes);

    render_object(GL_RGBA8, GL_UNSIGNED_BYTE, bytes, depth_values, sprite_tex, 1);
    depth_as_bytes(depth_values, depth_bytes);
    glViewport(0, 0, 10 * N, N);
    put_image(7 * N, N, bytes);
    put_image(8 * N, N, depth_bytes);

    render_object(GL_RGBA8, GL_UNSIGNED_BYTE, bytes, depth_values, sprite_tex, 2);
    glViewport(0, 0, 10 * N, N);
    put_image(9 * N, N, bytes);
    glDeleteTextures(1, &sprite_tex);
    scene_readpixels_check();
    return scene_end();
}
