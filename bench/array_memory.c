/* Memory benchmark: one glDrawArrays of 10 million lit vertices (GL_TRIANGLES,
 * float positions and normals from client arrays, 256x256, depth tested).
 * Prints the peak resident set size (getrusage ru_maxrss) before and after
 * the draw, and what the draw added. Built against Mesa's headers; run on
 * Mesa and on the drop-in by bench/run_memory.sh. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include "peak_rss.h"

int main(int argc, char **argv) {
    const long n = argc > 1 ? atol(argv[1]) : 10000000L;
    const int w = 256, h = 256;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    void *buf = malloc((size_t)w * h * 4);
    float *pos = malloc(sizeof(float) * 3 * n), *nrm = malloc(sizeof(float) * 3 * n);
    if (!ctx || !buf || !pos || !nrm || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h)) return 2;
    /* small triangles spread over the window, each facing a different way */
    for (long i = 0; i < n; i++) {
        long t = i / 3, k = i % 3;
        float x = (float)(t % 509) / 254.5f - 1.0f, y = (float)(t / 509 % 503) / 251.5f - 1.0f;
        pos[3 * i + 0] = x + (k == 1 ? 0.01f : 0.0f);
        pos[3 * i + 1] = y + (k == 2 ? 0.01f : 0.0f);
        pos[3 * i + 2] = -0.5f + (float)(t % 7) * 0.1f;
        nrm[3 * i + 0] = (float)(t % 13) / 13.0f - 0.5f;
        nrm[3 * i + 1] = (float)(t % 11) / 11.0f - 0.5f;
        nrm[3 * i + 2] = 1.0f;
    }
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
    glDrawArrays(GL_TRIANGLES, 0, (GLsizei)n);
    glFinish();
    const long after = peak_rss_kib();
    printf("%ld lit vertices: peak RSS %.1f MiB before the draw, %.1f MiB after; the draw added %.1f MiB\n", n,
           before / 1024.0, after / 1024.0, (after - before) / 1024.0);
    OSMesaDestroyContext(ctx);
    return 0;
}
