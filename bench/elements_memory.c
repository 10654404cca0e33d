/* Memory benchmark: one glDrawElements of 10 million indices (GL_TRIANGLES,
 * 32-bit indices from client memory into a grid of lit vertices, 256x256,
 * depth tested). Prints the peak resident set size (getrusage ru_maxrss)
 * before and after the draw, and what the draw added. Built against Mesa's
 * headers; run on Mesa and on the drop-in by bench/run_memory.sh. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include "peak_rss.h"

int main(int argc, char **argv) {
    const long n = argc > 1 ? atol(argv[1]) : 10000000L;
    const int w = 256, h = 256, gw = 300, gh = 300;
    const long nv = (long)gw * gh;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    void *buf = malloc((size_t)w * h * 4);
    float *pos = malloc(sizeof(float) * 3 * nv), *nrm = malloc(sizeof(float) * 3 * nv);
    GLuint *idx = malloc(sizeof(GLuint) * n);
    if (!ctx || !buf || !pos || !nrm || !idx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h)) return 2;
    for (long i = 0; i < nv; i++) {
        pos[3 * i + 0] = (float)(i % gw) / (gw / 2.0f) - 1.0f;
        pos[3 * i + 1] = (float)(i / gw) / (gh / 2.0f) - 1.0f;
        pos[3 * i + 2] = -0.5f + (float)(i % 7) * 0.1f;
        nrm[3 * i + 0] = (float)(i % 13) / 13.0f - 0.5f;
        nrm[3 * i + 1] = (float)(i % 11) / 11.0f - 0.5f;
        nrm[3 * i + 2] = 1.0f;
    }
    /* small triangles of grid neighbours, visited in a scattered order */
    for (long t = 0; t < n / 3; t++) {
        long c = (t * 7919) % ((long)(gw - 1) * (gh - 1)), x = c % (gw - 1), y = c / (gw - 1);
        idx[3 * t + 0] = (GLuint)(y * gw + x);
        idx[3 * t + 1] = (GLuint)(y * gw + x + 1);
        idx[3 * t + 2] = (GLuint)((y + 1) * gw + x);
    }
    for (long i = n / 3 * 3; i < n; i++) idx[i] = 0;
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, pos);
    glNormalPointer(GL_FLOAT, 0, nrm);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glFinish();
    const long before = peak_rss_kib();
    glDrawElements(GL_TRIANGLES, (GLsizei)n, GL_UNSIGNED_INT, idx);
    glFinish();
    const long after = peak_rss_kib();
    printf("%ld indices: peak RSS %.1f MiB before the draw, %.1f MiB after; the draw added %.1f MiB\n", n,
           before / 1024.0, after / 1024.0, (after - before) / 1024.0);
    OSMesaDestroyContext(ctx);
    return 0;
}
