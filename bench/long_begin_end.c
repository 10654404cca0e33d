/* Memory of one very long glBegin/glEnd: N lit vertices (glNormal3f and
 * glVertex3f, GL_TRIANGLES, small triangles across a 256x256 window) between
 * one glBegin and one glEnd, then glFinish. Prints the process's peak
 * resident set (getrusage ru_maxrss) before and after the draw. Built against
 * Mesa's headers; bench/run_memory.sh runs it on Mesa and on libglfixed. */
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
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h)) return 2;
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glFinish();
    const long before = peak_rss_kib();
    glBegin(GL_TRIANGLES);
    for (long i = 0; i < n / 3; i++) {
        /* a 2-pixel triangle somewhere on a 64x64 grid of cells */
        const float x = -1 + (float)(i % 64) / 32, y = -1 + (float)((i / 64) % 64) / 32;
        glNormal3f(0, 0, 1); glVertex3f(x, y, 0);
        glNormal3f(0, 0.6f, 0.8f); glVertex3f(x + 0.02f, y, 0);
        glNormal3f(0.6f, 0, 0.8f); glVertex3f(x, y + 0.02f, 0);
    }
    glEnd();
    glFinish();
    printf("%ld vertices: peak RSS %ld kB before glBegin, %ld kB after glEnd\n", n, before, peak_rss_kib());
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
