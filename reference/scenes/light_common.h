/* light_common.h - shared geometry and set-up for the light_* scenes.
 *
 * Everything here is plain legacy GL 1.x: hand-built spheres (latitude /
 * longitude bands), finely tessellated planes, viewport grids, and small
 * wrappers for glLightfv / glMaterialfv.  Lit colours keep the default
 * diffuse alpha of 1.0, so lit geometry never matches the KEY colour
 * (whose alpha is 0); scenes with overlapping objects enable GL_DEPTH_TEST. */
#ifndef LIGHT_COMMON_H
#define LIGHT_COMMON_H
#include "scene.h"
#include <math.h>

#define LIGHT_PI 3.14159265358979323846

/* ---- state helpers ---------------------------------------------------- */
static inline void light_fv(GLenum light, GLenum pname, float a, float b, float c, float d)
{
    GLfloat v[4];
    v[0] = a; v[1] = b; v[2] = c; v[3] = d;
    glLightfv(light, pname, v);
}

static inline void light_mat(GLenum face, GLenum pname, float a, float b, float c, float d)
{
    GLfloat v[4];
    v[0] = a; v[1] = b; v[2] = c; v[3] = d;
    glMaterialfv(face, pname, v);
}

static inline void light_model_ambient(float r, float g, float b, float a)
{
    GLfloat v[4];
    v[0] = r; v[1] = g; v[2] = b; v[3] = a;
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, v);
}

/* Every light colour and material colour to zero (global ambient too,
 * alphas 1), so a scene switches on exactly what it tests.  Attenuation and
 * spot parameters are left alone. */
static inline void light_all_black(void)
{
    int i;
    light_model_ambient(0.0f, 0.0f, 0.0f, 1.0f);
    for (i = 0; i < 8; i++) {
        light_fv(GL_LIGHT0 + i, GL_AMBIENT, 0.0f, 0.0f, 0.0f, 1.0f);
        light_fv(GL_LIGHT0 + i, GL_DIFFUSE, 0.0f, 0.0f, 0.0f, 1.0f);
        light_fv(GL_LIGHT0 + i, GL_SPECULAR, 0.0f, 0.0f, 0.0f, 1.0f);
    }
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.0f, 0.0f, 0.0f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.0f, 0.0f, 0.0f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.0f, 0.0f, 0.0f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_EMISSION, 0.0f, 0.0f, 0.0f, 1.0f);
}

/* ---- projections / viewports ------------------------------------------ */
/* Viewport = cell i of a grid with `cols` columns of cw x ch pixels, cells
 * numbered left to right, top row first. */
static inline void light_cell(int i, int cols, int rows, int cw, int ch)
{
    int cx = i % cols, cy = rows - 1 - i / cols;
    glViewport(cx * cw, cy * ch, cw, ch);
}

/* Orthographic view of [-s,s]^2 (scaled by the aspect), z in [-10,10].
 * The window is shifted by a fraction of a pixel so that the meshes'
 * symmetric edges do not run exactly through pixel centres (these scenes
 * test lighting, not the fill rule's tie-breaking). */
static inline void light_ortho(float s, float aspect)
{
    double ox = 0.0037 * s, oy = 0.0021 * s;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-s * aspect + ox, s * aspect + ox, -s + oy, s + oy, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Perspective frustum, eye at the origin looking down -z. */
static inline void light_frustum(float half_h, float aspect, float n, float f)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-half_h * aspect, half_h * aspect, -half_h, half_h, n, f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* ---- geometry ---------------------------------------------------------- */
/* Sphere of radius r at the origin from `stacks` latitude bands (quad
 * strips) and `slices` longitude steps, outward CCW faces, unit normals.
 * Poles on the +-y axis. */
static inline void light_sphere(float r, int slices, int stacks)
{
    int i, j;
    for (i = 0; i < stacks; i++) {
        double t0 = LIGHT_PI * i / stacks, t1 = LIGHT_PI * (i + 1) / stacks;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= slices; j++) {
            double p = 2.0 * LIGHT_PI * (j % slices) / slices;
            float x0 = (float)(sin(t0) * cos(p)), y0 = (float)cos(t0), z0 = (float)(-sin(t0) * sin(p));
            float x1 = (float)(sin(t1) * cos(p)), y1 = (float)cos(t1), z1 = (float)(-sin(t1) * sin(p));
            glNormal3f(x0, y0, z0);
            glVertex3f(r * x0, r * y0, r * z0);
            glNormal3f(x1, y1, z1);
            glVertex3f(r * x1, r * y1, r * z1);
        }
        glEnd();
    }
}

/* Plane z = z0 over [x0,x1]x[y0,y1], nx*ny cells as quad strips, normal +z,
 * CCW seen from +z. */
static inline void light_grid(float x0, float y0, float x1, float y1, float z0, int nx, int ny)
{
    int i, j;
    glNormal3f(0.0f, 0.0f, 1.0f);
    for (j = 0; j < ny; j++) {
        float ya = y0 + (y1 - y0) * j / ny, yb = y0 + (y1 - y0) * (j + 1) / ny;
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= nx; i++) {
            float x = x0 + (x1 - x0) * i / nx;
            glVertex3f(x, yb, z0);
            glVertex3f(x, ya, z0);
        }
        glEnd();
    }
}

/* Floor y = y0 over [x0,x1]x[z0,z1], normal +y, CCW seen from above. */
static inline void light_floor(float x0, float z0, float x1, float z1, float y0, int nx, int nz)
{
    int i, j;
    glNormal3f(0.0f, 1.0f, 0.0f);
    for (j = 0; j < nz; j++) {
        float za = z0 + (z1 - z0) * j / nz, zb = z0 + (z1 - z0) * (j + 1) / nz;
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= nx; i++) {
            float x = x0 + (x1 - x0) * i / nx;
            glVertex3f(x, y0, za);
            glVertex3f(x, y0, zb);
        }
        glEnd();
    }
}

/* Open cylinder around the y axis, radius r, y in [y0,y1], outward normals,
 * outward faces CCW.  `from`..`to` are angles in degrees (360 = closed
 * tube), measured from +x towards -z. */
static inline void light_tube(float r, float y0, float y1, float from, float to, int slices, int stacks)
{
    int i, j;
    for (i = 0; i < stacks; i++) {
        float ya = y0 + (y1 - y0) * i / stacks, yb = y0 + (y1 - y0) * (i + 1) / stacks;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= slices; j++) {
            double p = (from + (to - from) * j / slices) * LIGHT_PI / 180.0;
            float c = (float)cos(p), s = (float)-sin(p);
            glNormal3f(c, 0.0f, s);
            glVertex3f(r * c, yb, r * s);
            glVertex3f(r * c, ya, r * s);
        }
        glEnd();
    }
}

/* ---- shared scene bodies (scenes that exist in several variants) ------- */

/* Attenuation: a point light in front of a tessellated back wall, a floor
 * and a sphere, perspective (glFrustum).  light_atten_* scenes. */
static inline int light_atten_scene(int argc, char **argv, float kc, float kl, float kq)
{
    scene_begin(argc, argv, 128, 128);
    light_frustum(0.5f, 1.0f, 1.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    /* the ambient term of a positional light is attenuated as well */
    light_fv(GL_LIGHT0, GL_AMBIENT, 0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.4f, 0.3f, -2.2f, 1.0f);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, kc);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, kl);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, kq);
    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.8f, 0.6f, 1.0f);
    light_grid(-1.6f, -1.6f, 1.6f, 1.6f, -3.0f, 40, 40);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.5f, 0.9f, 0.5f, 1.0f);
    light_floor(-1.6f, -3.0f, 1.6f, -1.0f, -0.9f, 32, 20);
    glPushMatrix();
    glTranslatef(0.45f, -0.35f, -2.4f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.5f, 0.7f, 0.95f, 1.0f);
    light_sphere(0.35f, 32, 16);
    glPopMatrix();
    return scene_end();
}

/* Local viewer: three shiny spheres and a shiny floor under a wide
 * perspective; only GL_LIGHT_MODEL_LOCAL_VIEWER differs between the two
 * light_local_viewer_* scenes. */
static inline int light_local_viewer_scene(int argc, char **argv, int local)
{
    int i;
    scene_begin(argc, argv, 192, 128);
    light_frustum(0.75f, 1.5f, 1.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_all_black();
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local ? GL_TRUE : GL_FALSE);
    light_model_ambient(0.11f, 0.11f, 0.11f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 1.0f, 0.8f, 0.0f);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.3f, 0.3f, 0.5f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPECULAR, 0.9f, 0.8f, 0.3f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, -1.2f, 0.6f, -2.0f, 1.0f);
    /* camera looks down onto the floor by 20 degrees */
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.2f, 0.35f, 0.2f, 1.0f);
    light_floor(-5.0f, -8.0f, 5.0f, 0.0f, -1.3f, 60, 48);
    for (i = 0; i < 3; i++) {
        glPushMatrix();
        glTranslatef(-1.7f + 1.7f * i, -0.5f, -3.4f + 0.4f * (i & 1));
        light_mat(GL_FRONT, GL_DIFFUSE, 0.6f - 0.2f * i, 0.2f + 0.1f * i, 0.2f + 0.3f * i, 1.0f);
        light_sphere(0.75f, 40, 20);
        glPopMatrix();
    }
    return scene_end();
}

/* Colour control: shiny spheres with saturating highlights, coloured
 * diffuse, smooth shading; two 128x128 cells side by side at window row y0.
 * The right cell is a coarse sphere, or with `textured` the same fine
 * sphere under a GL_MODULATE checker texture (where
 * GL_SEPARATE_SPECULAR_COLOR keeps the highlight white). */
static inline void light_color_control_draw(GLenum control, int textured, int y0)
{
    static GLubyte tex[8][8][4];
    GLuint name = 0;
    int i, j;
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, control);
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.5f, 0.7f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 1.0f, 1.0f, 1.0f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.0f);
    if (textured) {
        for (j = 0; j < 8; j++)
            for (i = 0; i < 8; i++) {
                int on = (i ^ j) & 1;
                tex[j][i][0] = on ? 60 : 255;
                tex[j][i][1] = on ? 40 : 230;
                tex[j][i][2] = on ? 160 : 120;
                tex[j][i][3] = 255;
            }
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D, name);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }
    for (i = 0; i < 2; i++) {
        light_ortho(1.05f, 1.0f);
        glViewport(i * 128, y0, 128, 128);
        if (textured && i == 1)
            glEnable(GL_TEXTURE_2D);
        light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.3f, 0.1f, 1.0f);
        /* sphere with s along the longitude, t along the latitude; the
         * untextured right cell is coarse, where interpolating one clamped
         * sum differs most from two separately clamped terms */
        {
            int a, b, slices = (i == 1 && !textured) ? 10 : 32, stacks = (i == 1 && !textured) ? 6 : 16;
            for (a = 0; a < stacks; a++) {
                double t0 = LIGHT_PI * a / stacks, t1 = LIGHT_PI * (a + 1) / stacks;
                glBegin(GL_QUAD_STRIP);
                for (b = 0; b <= slices; b++) {
                    double p = 2.0 * LIGHT_PI * b / slices - LIGHT_PI / 2.0;
                    float x0 = (float)(sin(t0) * cos(p)), y0 = (float)cos(t0), z0 = (float)(-sin(t0) * sin(p));
                    float x1 = (float)(sin(t1) * cos(p)), y1 = (float)cos(t1), z1 = (float)(-sin(t1) * sin(p));
                    glTexCoord2f(2.0f * b / slices, 1.0f * a / stacks);
                    glNormal3f(x0, y0, z0);
                    glVertex3f(x0, y0, z0);
                    glTexCoord2f(2.0f * b / slices, 1.0f * (a + 1) / stacks);
                    glNormal3f(x1, y1, z1);
                    glVertex3f(x1, y1, z1);
                }
                glEnd();
            }
        }
        glDisable(GL_TEXTURE_2D);
    }
    if (name)
        glDeleteTextures(1, &name);
}

/* glColorMaterial(face, mode) on an open tube whose outside (front faces)
 * and inside (back faces) are both visible, two-sided lighting, 2x2 cells:
 *   0: GL_FRONT,          glColor per vertex, one directional light
 *   1: GL_FRONT_AND_BACK, glColor per vertex, one directional light
 *   2: GL_BACK,           one glColor for the whole tube, lit
 *   3: GL_BACK,           glColor per vertex, no light (scene colour only)
 * GL_BACK with a per-vertex colour AND a light is left out on purpose: Mesa
 * 22.3's fixed-function vertex program then computes only the red channel
 * of the back light products (green/blue/alpha come from an uninitialised
 * temporary, and llvmpipe and softpipe disagree). */
static inline void light_color_material_tube(int per_vertex)
{
    int i, j;
    for (i = 0; i < 8; i++) {
        float ya = -0.8f + 0.2f * i, yb = ya + 0.2f;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= 30; j++) {
            double p = (270.0 * j / 30) * LIGHT_PI / 180.0;
            float cx = (float)cos(p), sz = (float)-sin(p);
            float h = (float)j / 30.0f;
            glNormal3f(cx, 0.0f, sz);
            if (per_vertex)
                glColor4f(h, 0.2f + 0.1f * i, 1.0f - h, 0.41f + 0.57f * h);
            glVertex3f(0.9f * cx, yb, 0.9f * sz);
            if (per_vertex)
                glColor4f(1.0f - 0.1f * i, h * 0.8f, 0.3f, 1.0f - 0.047f * i);
            glVertex3f(0.9f * cx, ya, 0.9f * sz);
        }
        glEnd();
    }
}

static inline int light_color_material_scene(int argc, char **argv, GLenum mode)
{
    static const GLenum faces[4] = { GL_FRONT, GL_FRONT_AND_BACK, GL_BACK, GL_BACK };
    int c;
    scene_begin(argc, argv, 256, 256);
    for (c = 0; c < 4; c++) {
        light_cell(c, 2, 2, 128, 128);
        light_frustum(0.32f, 1.0f, 1.0f, 20.0f);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        light_all_black();
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        light_model_ambient(0.3f, 0.3f, 0.3f, 1.0f);
        if (c < 3)
            glEnable(GL_LIGHT0);
        else
            glDisable(GL_LIGHT0);
        light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
        light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
        light_fv(GL_LIGHT0, GL_POSITION, 0.6f, 0.5f, 1.0f, 0.0f);
        /* untracked material: visible but neutral */
        light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.25f, 0.25f, 0.25f, 1.0f);
        light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.45f, 0.45f, 0.45f, 1.0f);
        light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1.0f);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
        glTranslatef(0.0f, 0.0f, -4.0f);
        glRotatef(-25.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
        glColorMaterial(faces[c], mode);
        glEnable(GL_COLOR_MATERIAL);
        /* glColor after the enable: Mesa 22.3 applies the glMaterial calls
         * above only after glEnable(GL_COLOR_MATERIAL) has copied the
         * current colour, so a colour set before the enable would lose */
        glColor4f(0.2f, 0.7f, 0.9f, 0.8f);
        light_color_material_tube(c != 2);
        glDisable(GL_COLOR_MATERIAL);
    }
    return scene_end();
}

/* Two-sided lighting on an open tube (outside and inside both visible),
 * front material warm, back material cool; a directional light and a point
 * light inside the tube.  two_side: GL_LIGHT_MODEL_TWO_SIDE; front_face:
 * glFrontFace.  light_two_sided_tube / light_two_sided_cw /
 * light_one_sided_tube. */
static inline int light_tube_scene(int argc, char **argv, int two_side, GLenum front_face)
{
    scene_begin(argc, argv, 160, 160);
    light_frustum(0.4f, 1.0f, 1.0f, 20.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_all_black();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two_side ? GL_TRUE : GL_FALSE);
    glFrontFace(front_face);
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.5f, 0.8f, 1.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -4.5f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    /* the point light sits inside the tube, set under the object's modelview */
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.9f, 0.8f, 0.3f, 1.0f);
    light_fv(GL_LIGHT1, GL_SPECULAR, 0.9f, 0.8f, 0.3f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, 0.2f, 0.3f, 0.1f, 1.0f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.8f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.9f, 0.5f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.9f, 0.5f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
    light_mat(GL_BACK, GL_AMBIENT, 0.3f, 0.5f, 0.9f, 1.0f);
    light_mat(GL_BACK, GL_DIFFUSE, 0.3f, 0.6f, 0.9f, 1.0f);
    light_mat(GL_BACK, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    glMaterialf(GL_BACK, GL_SHININESS, 60.0f);
    light_tube(0.9f, -0.9f, 0.9f, 0.0f, 290.0f, 48, 12);
    return scene_end();
}

/* A wavy 10x10 mesh of triangle strips with glMaterialfv(GL_FRONT, ...)
 * diffuse / specular / emission / shininess changing per vertex inside
 * glBegin/glEnd.  light_material_per_vertex_* scenes. */
static inline void light_material_mesh(void)
{
    int i, j;
    for (j = 0; j < 10; j++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i <= 10; i++) {
            int k;
            for (k = 1; k >= 0; k--) {
                float u = i / 10.0f, v = (j + k) / 10.0f;
                float x = -1.0f + 2.0f * u, y = -1.0f + 2.0f * v;
                float z = 0.3f * (float)sin(3.0 * x) * (float)cos(2.0 * y);
                float nx = -0.9f * (float)cos(3.0 * x) * (float)cos(2.0 * y);
                float ny = 0.6f * (float)sin(3.0 * x) * (float)sin(2.0 * y);
                float nl = (float)sqrt(nx * nx + ny * ny + 1.0f);
                GLfloat dif[4], spe[4], emi[4];
                dif[0] = u; dif[1] = 0.3f + 0.5f * v; dif[2] = 1.0f - u; dif[3] = 1.0f;
                spe[0] = spe[1] = spe[2] = v; spe[3] = 1.0f;
                emi[0] = 0.2f * ((i + j + k) & 1); emi[1] = 0.0f; emi[2] = 0.1f * u; emi[3] = 1.0f;
                glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
                glMaterialfv(GL_FRONT, GL_SPECULAR, spe);
                glMaterialfv(GL_FRONT, GL_EMISSION, emi);
                glMaterialf(GL_FRONT, GL_SHININESS, 5.0f + 60.0f * u);
                glNormal3f(nx / nl, ny / nl, 1.0f / nl);
                glVertex3f(x, y, z);
            }
        }
        glEnd();
    }
}

/* Unit-sphere point at latitude step i of `stacks`, longitude step j of
 * `slices`: normal and vertex (radius r). */
static inline void light_sphere_vertex(float r, int i, int j, int slices, int stacks)
{
    double t = LIGHT_PI * i / stacks, p = 2.0 * LIGHT_PI * (j % slices) / slices;
    float x = (float)(sin(t) * cos(p)), y = (float)cos(t), z = (float)(-sin(t) * sin(p));
    glNormal3f(x, y, z);
    glVertex3f(r * x, r * y, r * z);
}

/* The same sphere as light_sphere, but built from `prim`: GL_TRIANGLES,
 * GL_TRIANGLE_STRIP (one per band), GL_QUADS or GL_QUAD_STRIP (one per
 * band).  All faces CCW from outside. */
static inline void light_sphere_prim(float r, int slices, int stacks, GLenum prim)
{
    int i, j;
    if (prim == GL_TRIANGLES || prim == GL_QUADS) {
        glBegin(prim);
        for (i = 0; i < stacks; i++)
            for (j = 0; j < slices; j++) {
                if (prim == GL_QUADS) {
                    light_sphere_vertex(r, i, j, slices, stacks);
                    light_sphere_vertex(r, i + 1, j, slices, stacks);
                    light_sphere_vertex(r, i + 1, j + 1, slices, stacks);
                    light_sphere_vertex(r, i, j + 1, slices, stacks);
                } else {
                    light_sphere_vertex(r, i, j, slices, stacks);
                    light_sphere_vertex(r, i + 1, j, slices, stacks);
                    light_sphere_vertex(r, i + 1, j + 1, slices, stacks);
                    light_sphere_vertex(r, i + 1, j + 1, slices, stacks);
                    light_sphere_vertex(r, i, j + 1, slices, stacks);
                    light_sphere_vertex(r, i, j, slices, stacks);
                }
            }
        glEnd();
        return;
    }
    for (i = 0; i < stacks; i++) {
        glBegin(prim);
        for (j = 0; j <= slices; j++) {
            light_sphere_vertex(r, i, j, slices, stacks);
            light_sphere_vertex(r, i + 1, j, slices, stacks);
        }
        glEnd();
    }
}

/* A dome of `n` rim vertices around (cx, cy): GL_TRIANGLE_FAN with a
 * centre vertex, or GL_POLYGON of the rim only; rim normals tilted out. */
static inline void light_dome(GLenum prim, float cx, float cy, float rad, int n, float phase)
{
    int k;
    glBegin(prim);
    if (prim == GL_TRIANGLE_FAN) {
        glNormal3f(0.0f, 0.0f, 1.0f);
        glVertex3f(cx, cy, 0.3f);
    }
    for (k = 0; k <= n; k++) {
        double a;
        float c, s;
        if (prim == GL_POLYGON && k == n)
            break;
        a = phase + 2.0 * LIGHT_PI * k / n;
        c = (float)cos(a);
        s = (float)sin(a);
        glNormal3f(0.8f * c, 0.8f * s, 0.6f);
        glVertex3f(cx + rad * c, cy + rad * s, 0.0f);
    }
    glEnd();
}

/* Flat shading on lit meshes: 3x2 cells GL_TRIANGLES, GL_TRIANGLE_STRIP,
 * GL_TRIANGLE_FAN / GL_QUADS, GL_QUAD_STRIP, GL_POLYGON, every vertex with
 * its own smooth normal, so the provoking vertex's lighting decides each
 * face's colour.  first: glProvokingVertex(GL_FIRST_VERTEX_CONVENTION). */
static inline int light_flat_scene(int argc, char **argv, int first)
{
    int c;
    scene_begin(argc, argv, 384, 256);
    glShadeModel(GL_FLAT);
    if (first)
        glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.15f, 0.15f, 0.15f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.5f, 0.7f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.8f, 0.7f, 0.5f, 1.0f);
    light_mat(GL_FRONT, GL_DIFFUSE, 0.8f, 0.6f, 0.3f, 1.0f);
    light_mat(GL_FRONT, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT, GL_SHININESS, 15.0f);
    for (c = 0; c < 6; c++) {
        light_cell(c, 3, 2, 128, 128);
        light_ortho(1.0f, 1.0f);
        glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(15.0f, 0.0f, 1.0f, 0.0f);
        switch (c) {
        case 0: light_sphere_prim(0.9f, 12, 8, GL_TRIANGLES); break;
        case 1: light_sphere_prim(0.9f, 12, 8, GL_TRIANGLE_STRIP); break;
        case 2:
            light_dome(GL_TRIANGLE_FAN, -0.45f, 0.45f, 0.42f, 7, 0.0);
            light_dome(GL_TRIANGLE_FAN, 0.45f, 0.45f, 0.42f, 5, 0.4);
            light_dome(GL_TRIANGLE_FAN, -0.45f, -0.45f, 0.42f, 9, 0.2);
            light_dome(GL_TRIANGLE_FAN, 0.45f, -0.45f, 0.42f, 6, 0.7);
            break;
        case 3: light_sphere_prim(0.9f, 12, 8, GL_QUADS); break;
        case 4: light_sphere_prim(0.9f, 12, 8, GL_QUAD_STRIP); break;
        case 5:
            /* the first rim vertex points a different way in each */
            light_dome(GL_POLYGON, -0.45f, 0.45f, 0.42f, 7, 2.2);
            light_dome(GL_POLYGON, 0.45f, 0.45f, 0.42f, 5, 1.2);
            light_dome(GL_POLYGON, -0.45f, -0.45f, 0.42f, 9, 3.0);
            light_dome(GL_POLYGON, 0.45f, -0.45f, 0.42f, 6, 4.4);
            break;
        }
    }
    return scene_end();
}

#endif
