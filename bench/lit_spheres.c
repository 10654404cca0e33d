/* Benchmark: a legacy program drawing lit smooth spheres in immediate mode
 * (about 20k triangles a frame, 512x512, depth tested, 2 lights), the same
 * spheres compiled once into a display list and replayed ("list"), the same
 * vertices in one buffer object drawn with glMultiDrawArrays ("vbo"),
 * full-screen lit quads for fill ("fill"), and the same quads under a
 * trilinear (GL_LINEAR_MIPMAP_LINEAR) GL_MODULATE texture ("texfill"; 1.5
 * texels a pixel, so every pixel blends two levels), and the same quads
 * blended, SRC_ALPHA / ONE_MINUS_SRC_ALPHA with a diffuse alpha of 0.5
 * ("blendfill": every pixel reads the buffer), and the same quads in GL_EXP2
 * fog ("fogfill": each pixel's fog factor through llvmpipe's exp2), and a
 * 1024x1024 RGBA texture uploaded by glTexImage2D every frame, then drawn on a
 * small quad ("upload": streaming video frames or procedural textures). Built against Mesa's
 * headers; run on Mesa and on the drop-in by bench/run_bench.sh. Prints ms
 * per frame. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static void sphere(float cx, float cy, float cz, float r, int slices, int stacks) {
    for (int i = 0; i < stacks; i++) {
        float a0 = (float)M_PI * i / stacks - (float)M_PI / 2, a1 = (float)M_PI * (i + 1) / stacks - (float)M_PI / 2;
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= slices; j++) {
            float b = 2 * (float)M_PI * j / slices;
            float x0 = cosf(a0) * cosf(b), y0 = sinf(a0), z0 = cosf(a0) * sinf(b);
            float x1 = cosf(a1) * cosf(b), y1 = sinf(a1), z1 = cosf(a1) * sinf(b);
            glNormal3f(x1, y1, z1); glVertex3f(cx + r * x1, cy + r * y1, cz + r * z1);
            glNormal3f(x0, y0, z0); glVertex3f(cx + r * x0, cy + r * y0, cz + r * z0);
        }
        glEnd();
    }
}

/* The spheres' quad strips as interleaved normal + position floats (GL_N3F_V3F
 * order), the same values sphere() passes to glNormal3f/glVertex3f. */
static int sphere_vertices(float *out, GLint *first, GLsizei *count, int strip0, float cx, float cy, float cz,
                           float r, int slices, int stacks) {
    int n = 0;
    for (int i = 0; i < stacks; i++) {
        float a0 = (float)M_PI * i / stacks - (float)M_PI / 2, a1 = (float)M_PI * (i + 1) / stacks - (float)M_PI / 2;
        first[strip0 + i] = n;
        for (int j = 0; j <= slices; j++) {
            float b = 2 * (float)M_PI * j / slices;
            float x0 = cosf(a0) * cosf(b), y0 = sinf(a0), z0 = cosf(a0) * sinf(b);
            float x1 = cosf(a1) * cosf(b), y1 = sinf(a1), z1 = cosf(a1) * sinf(b);
            float v[12] = {x1, y1, z1, cx + r * x1, cy + r * y1, cz + r * z1,
                           x0, y0, z0, cx + r * x0, cy + r * y0, cz + r * z0};
            memcpy(out + n * 6, v, sizeof v);
            n += 2;
        }
        count[strip0 + i] = n - first[strip0 + i];
    }
    return n;
}

int main(int argc, char **argv) {
    const int w = 512, h = 512, frames = argc > 1 ? atoi(argv[1]) : 20;
    const char *what = argc > 2 ? argv[2] : "geometry";
    double t0 = now();
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    void *buf = malloc((size_t)w * h * 4);
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h)) return 2;
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    const GLfloat p0[4] = {1, 1, 1, 0}, p1[4] = {-2, 1, 2, 1}, d1[4] = {0.6f, 0.5f, 0.3f, 1};
    const GLfloat spec[4] = {1, 1, 1, 1}, diff[4] = {0.7f, 0.3f, 0.2f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, p0);
    glLightfv(GL_LIGHT1, GL_POSITION, p1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, d1);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diff);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 30);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 2, 20);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -6);
    const int list = strcmp(what, "list") == 0;
    if (list) {  /* compiled before the timing: only the replays are timed */
        glNewList(1, GL_COMPILE);
        for (int s = 0; s < 4; s++) sphere(-1.5f + s, (s % 2) - 0.5f, 0, 0.9f, 64, 40);
        glEndList();
    }
    const int vbo = strcmp(what, "vbo") == 0;
    enum { kSlices = 64, kStacks = 40, kStrips = 4 * kStacks };
    static GLint first[kStrips];
    static GLsizei count[kStrips];
    if (vbo) {  /* uploaded before the timing: only the draws are timed */
        static float data[4 * kStacks * (kSlices + 1) * 2 * 6];
        int n = 0;
        for (int s = 0; s < 4; s++) {
            int base = n;
            n += sphere_vertices(data + n * 6, first, count, s * kStacks, -1.5f + s, (s % 2) - 0.5f, 0, 0.9f,
                                 kSlices, kStacks);
            for (int i = 0; i < kStacks; i++) first[s * kStacks + i] += base;
        }
        GLuint buffer;
        glGenBuffers(1, &buffer);
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * 6 * sizeof(float)), data, GL_STATIC_DRAW);
        glInterleavedArrays(GL_N3F_V3F, 0, (const void *)0);
    }
    const int texfill = strcmp(what, "texfill") == 0;
    if (texfill) {  /* uploaded before the timing: a 256x256 checker, every level by glTexImage2D */
        static unsigned char img[2][256 * 256 * 4];
        for (int y = 0; y < 256; y++)
            for (int x = 0; x < 256; x++) {
                unsigned char *p = img[0] + 4 * (y * 256 + x);
                int on = ((x / 16) ^ (y / 16)) & 1;
                p[0] = (unsigned char)(on ? 230 : 60 + x / 4);
                p[1] = (unsigned char)(on ? 220 : 90 + y / 4);
                p[2] = (unsigned char)(on ? 200 : 150);
                p[3] = 255;
            }
        GLuint tex;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        int size = 256, cur = 0;
        for (int level = 0;; level++) {
            glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, img[cur]);
            if (size == 1) break;
            const int half = size / 2;  /* 2x2 box filter into the other buffer */
            for (int y = 0; y < half; y++)
                for (int x = 0; x < half; x++)
                    for (int c = 0; c < 4; c++) {
                        const unsigned char *q = img[cur] + 4 * (2 * y * size + 2 * x) + c;
                        img[!cur][4 * (y * half + x) + c] =
                            (unsigned char)((q[0] + q[4] + q[4 * size] + q[4 * size + 4] + 2) / 4);
                    }
            size = half;
            cur = !cur;
        }
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glEnable(GL_TEXTURE_2D);
    }
    const int blendfill = strcmp(what, "blendfill") == 0;
    if (blendfill) {  /* translucent lit quads over each other */
        const GLfloat diffuse[4] = {0.8f, 0.6f, 0.4f, 0.5f};
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_BLEND);
    }
    const int fogfill = strcmp(what, "fogfill") == 0;
    if (fogfill) {  /* the fill quads in GL_EXP2 fog */
        const GLfloat fogColor[4] = {0.5f, 0.55f, 0.6f, 1};
        glFogfv(GL_FOG_COLOR, fogColor);
        glFogi(GL_FOG_MODE, GL_EXP2);
        glFogf(GL_FOG_DENSITY, 0.2f);
        glEnable(GL_FOG);
    }
    const int upload = strcmp(what, "upload") == 0;
    enum { kUploadSize = 1024 };
    static unsigned char frame[kUploadSize * kUploadSize * 4];
    if (upload) {
        for (int i = 0; i < kUploadSize * kUploadSize * 4; i++) frame[i] = (unsigned char)(i * 7 + (i >> 12));
        GLuint tex;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glEnable(GL_TEXTURE_2D);
        glDisable(GL_LIGHTING);
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFinish();
    double t1 = now();
    for (int f = 0; f < frames; f++) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (strcmp(what, "fill") == 0 || texfill || blendfill || fogfill) {
            for (int q = 0; q < 8; q++) {  /* 8 full-screen lit quads, back to front */
                /* texfill: s and t run over 3 texture widths across the 512 pixels (the
                 * window is 6 - z units wide at the quad's depth), shifted per quad */
                const float z = 1 - q * 0.1f, k = 3.0f / (6 - z), o = 0.37f * q;
                const float xy[4][2] = {{-3, -3}, {3, -3}, {3, 3}, {-3, 3}};
                glNormal3f(0, 0, 1);
                glBegin(GL_QUADS);
                for (int v = 0; v < 4; v++) {
                    if (texfill) glTexCoord2f(o + k * xy[v][0], o + k * xy[v][1]);
                    glVertex3f(xy[v][0], xy[v][1], z);
                }
                glEnd();
            }
        } else if (upload) {
            frame[f % sizeof frame] ^= 0xff;  /* a new frame each time */
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kUploadSize, kUploadSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, frame);
            glBegin(GL_QUADS);  /* about 30x30 pixels */
            glTexCoord2f(0, 0); glVertex3f(-0.15f, -0.15f, 1);
            glTexCoord2f(1, 0); glVertex3f(0.15f, -0.15f, 1);
            glTexCoord2f(1, 1); glVertex3f(0.15f, 0.15f, 1);
            glTexCoord2f(0, 1); glVertex3f(-0.15f, 0.15f, 1);
            glEnd();
        } else if (list) {
            glCallList(1);
        } else if (vbo) {
            glMultiDrawArrays(GL_QUAD_STRIP, first, count, kStrips);
        } else {
            for (int s = 0; s < 4; s++) sphere(-1.5f + s, (s % 2) - 0.5f, 0, 0.9f, 64, 40);
        }
        glFinish();
    }
    double t2 = now();
    printf("%s: start-up + first clear %.1f ms, %.2f ms/frame\n", what, (t1 - t0) * 1e3, (t2 - t1) * 1e3 / frames);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
