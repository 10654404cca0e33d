/* program_common.c - the lit scene, the picture file and the memory report
 * the real programs share (see program_common.h). */
#include "program_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

void program_clear(void)
{
    glClearColor(PROGRAM_KEY_R / 255.0f, PROGRAM_KEY_G / 255.0f, PROGRAM_KEY_B / 255.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void program_lights_setup(void)
{
    /* Global ambient 0.25 in blue times a material blue >= 0.2 keeps every
     * lit pixel's blue above the KEY's 7 (see program_common.h). */
    static const GLfloat global_ambient[4] = {0.2f, 0.2f, 0.25f, 1.0f};
    static const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const GLfloat dim[4] = {0.05f, 0.05f, 0.05f, 1.0f};
    static const GLfloat warm[4] = {1.0f, 0.75f, 0.45f, 1.0f};
    static const GLfloat warm_specular[4] = {1.0f, 0.9f, 0.7f, 1.0f};

    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, global_ambient);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);

    /* Light 0: directional, white. */
    glLightfv(GL_LIGHT0, GL_AMBIENT, dim);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);

    /* Light 1: a warm spot light with attenuation. */
    glLightfv(GL_LIGHT1, GL_AMBIENT, dim);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT1, GL_SPECULAR, warm_specular);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 35.0f);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 6.0f);
    glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.8f);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.05f);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.01f);

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
}

void program_view(int width, int height, int frame)
{
    /* Given while the modelview matrix is the identity: eye space. */
    static const GLfloat sun_direction[4] = {-0.4f, 0.7f, 0.6f, 0.0f};
    const GLfloat aspect = height > 0 ? (GLfloat)width / (GLfloat)height : 1.0f;
    const GLfloat swing = 0.6f * sinf(program_angle(frame, 2.0f) * (float)M_PI / 180.0f);
    const GLfloat spot_position[4] = {1.5f + swing, 2.0f, 1.0f, 1.0f};
    const GLfloat spot_direction[3] = {-0.3f - 0.2f * swing, -0.5f, -1.0f};

    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, sun_direction);
    glLightfv(GL_LIGHT1, GL_POSITION, spot_position);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot_direction);
    glTranslatef(0.0f, 0.0f, -4.2f);
    glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
}

void program_material(float r, float g, float b, float shininess)
{
    const GLfloat color[4] = {r, g, b, 1.0f};
    static const GLfloat specular[4] = {0.8f, 0.8f, 0.8f, 1.0f};
    static const GLfloat no_emission[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, color);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, no_emission);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

float program_angle(int frame, float degrees_per_frame)
{
    return fmodf((float)frame * degrees_per_frame, 360.0f);
}

/* Point and normal of the unit sphere at stack i (0 = south pole) and slice j. */
static void sphere_point(int i, int j, int slices, int stacks, GLfloat n[3])
{
    const float phi = (float)M_PI * ((float)i / (float)stacks - 0.5f);
    const float theta = 2.0f * (float)M_PI * (float)j / (float)slices;
    n[0] = cosf(phi) * cosf(theta);
    n[1] = cosf(phi) * sinf(theta);
    n[2] = sinf(phi);
}

void program_sphere(float radius, int slices, int stacks)
{
    for (int i = 0; i < stacks; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= slices; j++) {
            GLfloat n[3];
            sphere_point(i + 1, j, slices, stacks, n);
            glNormal3fv(n);
            glVertex3f(radius * n[0], radius * n[1], radius * n[2]);
            sphere_point(i, j, slices, stacks, n);
            glNormal3fv(n);
            glVertex3f(radius * n[0], radius * n[1], radius * n[2]);
        }
        glEnd();
    }
}

void program_torus(float inner_radius, float outer_radius, int sides, int rings)
{
    for (int i = 0; i < rings; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= sides; j++) {
            const float phi = 2.0f * (float)M_PI * (float)j / (float)sides;
            for (int k = 1; k >= 0; k--) {
                const float theta = 2.0f * (float)M_PI * (float)(i + k) / (float)rings;
                const float ring = outer_radius + inner_radius * cosf(phi);
                glNormal3f(cosf(phi) * cosf(theta), cosf(phi) * sinf(theta), sinf(phi));
                glVertex3f(ring * cosf(theta), ring * sinf(theta), inner_radius * sinf(phi));
            }
        }
        glEnd();
    }
}

enum { MAX_SLICES = 48, MAX_STACKS = 24 };

void program_sphere_arrays(float radius, int slices, int stacks)
{
    static GLfloat positions[(MAX_SLICES + 1) * (MAX_STACKS + 1) * 3];
    static GLfloat normals[(MAX_SLICES + 1) * (MAX_STACKS + 1) * 3];
    static GLushort indices[MAX_SLICES * MAX_STACKS * 6];
    if (slices > MAX_SLICES) slices = MAX_SLICES;
    if (stacks > MAX_STACKS) stacks = MAX_STACKS;
    int v = 0;
    for (int i = 0; i <= stacks; i++)
        for (int j = 0; j <= slices; j++, v++) {
            sphere_point(i, j, slices, stacks, &normals[v * 3]);
            for (int c = 0; c < 3; c++) positions[v * 3 + c] = radius * normals[v * 3 + c];
        }
    int n = 0;
    for (int i = 0; i < stacks; i++)
        for (int j = 0; j < slices; j++) {
            const GLushort a = (GLushort)(i * (slices + 1) + j), b = (GLushort)(a + slices + 1);
            indices[n++] = a; indices[n++] = (GLushort)(a + 1); indices[n++] = (GLushort)(b + 1);
            indices[n++] = a; indices[n++] = (GLushort)(b + 1); indices[n++] = b;
        }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, indices);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

void program_draw_egl_scene(int width, int height, int frame)
{
    program_clear();
    program_view(width, height, frame);
    const float a = program_angle(frame, 3.0f);

    glPushMatrix();
    glTranslatef(-1.25f, 0.45f, 0.0f);
    glRotatef(a, 0.0f, 1.0f, 0.0f);
    glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
    program_material(0.85f, 0.25f, 0.2f, 40.0f);
    program_sphere(0.7f, 24, 12);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(1.1f, 0.35f, 0.0f);
    glRotatef(a, 0.3f, 1.0f, 0.0f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    program_material(0.2f, 0.75f, 0.3f, 60.0f);
    program_torus(0.22f, 0.6f, 16, 28);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.0f, -0.8f, 0.6f);
    glRotatef(-a, 0.0f, 0.0f, 1.0f);
    glRotatef(80.0f, 1.0f, 0.0f, 0.0f);
    program_material(0.3f, 0.4f, 0.9f, 20.0f);
    program_sphere_arrays(0.55f, 20, 10);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(0.1f, 1.0f, -1.0f);
    program_material(0.9f, 0.8f, 0.2f, 90.0f);
    program_sphere(0.3f, 12, 8);
    glPopMatrix();
}

int program_write_dump(const char *prefix, int width, int height, const unsigned char *rgba,
                       int coverage_channels, int frames)
{
    const GLenum error = glGetError();
    char path[4096];
    snprintf(path, sizeof path, "%s.glfx", prefix);
    FILE *f = fopen(path, "wb");
    if (!f) {
        perror(path);
        return -1;
    }
    fprintf(f, "GLFX1 %d %d %d 0 0 0 0 0\n", width, height, coverage_channels);
    fprintf(f, "info frames=%d gl_error=0x%04x\n", frames, (unsigned)error);
    const size_t bytes = (size_t)width * (size_t)height * 4;
    const int ok = fwrite(rgba, 1, bytes, f) == bytes;
    if (fclose(f) != 0 || !ok) {
        fprintf(stderr, "%s: write failed\n", path);
        return -1;
    }
    if (error != GL_NO_ERROR) {
        fprintf(stderr, "GL error 0x%04x after the last frame\n", (unsigned)error);
        return -1;
    }
    return 0;
}

long program_covered_pixels(int width, int height, const unsigned char *rgba)
{
    long covered = 0;
    for (size_t i = 0, n = (size_t)width * (size_t)height; i < n; i++)
        if (rgba[i * 4] != PROGRAM_KEY_R || rgba[i * 4 + 1] != PROGRAM_KEY_G ||
            rgba[i * 4 + 2] != PROGRAM_KEY_B)
            covered++;
    return covered;
}

int program_print_renderer(void)
{
    const GLubyte *renderer = glGetString(GL_RENDERER);
    const GLubyte *version = glGetString(GL_VERSION);
    if (!renderer || !version) {
        fprintf(stderr, "glGetString(GL_RENDERER / GL_VERSION) returned NULL (GL error 0x%04x)\n",
                (unsigned)glGetError());
        return -1;
    }
    printf("GL_RENDERER: %s\nGL_VERSION: %s\n", (const char *)renderer, (const char *)version);
    fflush(stdout);
    return 0;
}

long program_status_kb(const char *field)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f) return -1;
    char line[256];
    long kb = -1;
    const size_t len = strlen(field);
    while (fgets(line, sizeof line, f))
        if (strncmp(line, field, len) == 0 && line[len] == ':') {
            kb = strtol(line + len + 1, NULL, 10);
            break;
        }
    fclose(f);
    return kb;
}

void program_report_rss(int frame)
{
    printf("rss frame=%d VmRSS=%ld VmHWM=%ld\n", frame, program_status_kb("VmRSS"),
           program_status_kb("VmHWM"));
    fflush(stdout);
}

int program_frames_arg(const char *arg, int default_frames)
{
    if (!arg) return default_frames;
    char *end = NULL;
    const long n = strtol(arg, &end, 10);
    if (end == arg || *end != '\0' || n < 1 || n > 1000000) return -1;
    return (int)n;
}
