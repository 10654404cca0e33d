/* A shadow map through a framebuffer object: the depth of a scene (a torus
 * and a sphere over a floor) rendered from the light into a 128x128
 * DEPTH_COMPONENT24 texture (no colour buffer; polygon offset against acne
 * on the objects, none on the floor, whose acne tests every depth bit),
 * then the lit scene drawn from the camera with that texture on unit 0:
 * GL_TEXTURE_COMPARE_MODE GL_COMPARE_R_TO_TEXTURE (GL_LEQUAL),
 * GL_DEPTH_TEXTURE_MODE GL_LUMINANCE, linear filtering (percentage-closer),
 * GL_MODULATE, and eye-linear texgen on s, t, r, q whose planes are the rows
 * of bias * light projection * light view * inverse camera view (set with an
 * identity modelview). The object's depth comes from llvmpipe's y-up
 * rasterization; every shadowed pixel depends on it. */
#include "tex_common.h"

enum { SHADOW = 128 };

typedef double mat4[16]; /* column-major, as GL */

static void mat_identity(mat4 m)
{
    int i;
    for (i = 0; i < 16; i++)
        m[i] = (i % 5 == 0) ? 1.0 : 0.0;
}

static void mat_mul(const mat4 a, const mat4 b, mat4 out)
{
    mat4 r;
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s = 0.0;
            for (k = 0; k < 4; k++)
                s += a[k * 4 + i] * b[j * 4 + k];
            r[j * 4 + i] = s;
        }
    memcpy(out, r, sizeof r);
}

static void mat_translate(mat4 m, double x, double y, double z)
{
    mat4 t;
    mat_identity(t);
    t[12] = x;
    t[13] = y;
    t[14] = z;
    mat_mul(m, t, m);
}

static void mat_rotate_x(mat4 m, double deg)
{
    mat4 r;
    double a = deg * LIGHT_PI / 180.0;
    mat_identity(r);
    r[5] = cos(a);
    r[6] = sin(a);
    r[9] = -sin(a);
    r[10] = cos(a);
    mat_mul(m, r, m);
}

static void mat_rotate_y(mat4 m, double deg)
{
    mat4 r;
    double a = deg * LIGHT_PI / 180.0;
    mat_identity(r);
    r[0] = cos(a);
    r[2] = -sin(a);
    r[8] = sin(a);
    r[10] = cos(a);
    mat_mul(m, r, m);
}

static void mat_frustum(mat4 m, double l, double r, double b, double t, double n, double f)
{
    mat4 p;
    memset(p, 0, sizeof p);
    p[0] = 2 * n / (r - l);
    p[5] = 2 * n / (t - b);
    p[8] = (r + l) / (r - l);
    p[9] = (t + b) / (t - b);
    p[10] = -(f + n) / (f - n);
    p[11] = -1;
    p[14] = -2 * f * n / (f - n);
    mat_mul(m, p, m);
}

/* The light's and the camera's views: translate(0, 0, -d) rotx(a) roty(b). */
static const double kLight[3] = { 10.0, 58.0, -30.0 }, kCamera[3] = { 10.0, 28.0, 35.0 };

static void gl_view(const double v[3])
{
    glTranslatef(0.0f, 0.0f, (float)-v[0]);
    glRotatef((float)v[1], 1.0f, 0.0f, 0.0f);
    glRotatef((float)v[2], 0.0f, 1.0f, 0.0f);
}

/* `offset`: polygon offset on the torus and the sphere (the depth pass);
 * the floor never has it, so its self-shadowing (acne) depends on the last
 * bits of every depth value. */
static void scene_objects(int offset)
{
    int i, j;
    glColor3f(0.75f, 0.75f, 0.7f);
    glNormal3f(0.0f, 1.0f, 0.0f);
    for (j = 0; j < 8; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 8; i++) {
            glVertex3f(-2.5f + 5.0f * i / 8, -1.0f, -2.5f + 5.0f * (j + 1) / 8);
            glVertex3f(-2.5f + 5.0f * i / 8, -1.0f, -2.5f + 5.0f * j / 8);
        }
        glEnd();
    }
    if (offset) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(2.0f, 4.0f);
    }
    glPushMatrix();
    glTranslatef(-0.6f, 0.1f, 0.2f);
    glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.95f, 0.55f, 0.2f);
    tex_torus(0.8f, 0.28f, 24, 12);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.1f, -0.35f, -0.6f);
    glColor3f(0.3f, 0.6f, 0.95f);
    tex_sphere(0.65f, 18, 12, 1.0f);
    glPopMatrix();
    glDisable(GL_POLYGON_OFFSET_FILL);
}

int main(int argc, char **argv)
{
    static const GLenum coords[4] = { GL_S, GL_T, GL_R, GL_Q };
    static const GLenum gens[4] = { GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q };
    GLuint fb, tex;
    mat4 m, camera_inverse;
    int k;
    scene_begin(argc, argv, 160, 160);

    tex = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, SHADOW, SHADOW, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glBindTexture(GL_TEXTURE_2D, 0);

    /* The depth pass, from the light. */
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return 1;
    glViewport(0, 0, SHADOW, SHADOW);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 4.0, 16.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gl_view(kLight);
    scene_objects(1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);

    /* The texgen planes: bias * light projection * light view * camera view^-1. */
    mat_identity(m);
    mat_translate(m, 0.5, 0.5, 0.5);
    {
        mat4 s;
        mat_identity(s);
        s[0] = s[5] = s[10] = 0.5;
        mat_mul(m, s, m);
    }
    mat_frustum(m, -1.0, 1.0, -1.0, 1.0, 4.0, 16.0);
    mat_translate(m, 0.0, 0.0, -kLight[0]);
    mat_rotate_x(m, kLight[1]);
    mat_rotate_y(m, kLight[2]);
    mat_identity(camera_inverse);
    mat_rotate_y(camera_inverse, -kCamera[2]);
    mat_rotate_x(camera_inverse, -kCamera[1]);
    mat_translate(camera_inverse, 0.0, 0.0, kCamera[0]);
    mat_mul(m, camera_inverse, m);

    /* The camera pass. */
    glViewport(0, 0, 160, 160);
    scene_clear();
    light_frustum(0.6f, 1.0f, 2.0f, 20.0f);
    for (k = 0; k < 4; k++) {
        GLfloat plane[4] = { (GLfloat)m[k], (GLfloat)m[4 + k], (GLfloat)m[8 + k], (GLfloat)m[12 + k] };
        glTexGeni(coords[k], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glTexGenfv(coords[k], GL_EYE_PLANE, plane);
        glEnable(gens[k]);
    }
    gl_view(kCamera);
    tex_lights();
    glEnable(GL_COLOR_MATERIAL);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    scene_objects(0);
    glDisable(GL_TEXTURE_2D);
    for (k = 0; k < 4; k++)
        glDisable(gens[k]);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_LIGHTING);
    glDeleteTextures(1, &tex);
    scene_readpixels_check();
    return scene_end();
}
