/* Probe: Mesa 22.3.6 with GL_UNPACK_SWAP_BYTES and GL_UNPACK_SKIP_PIXELS or
 * GL_UNPACK_SKIP_ROWS uploads wrong texels (the skipped offset and the
 * swap do not agree; the wrong texels change from run to run). Uploads a
 * 5x4 GL_RGBA / GL_UNSIGNED_SHORT image into GL_RGBA16 under several unpack
 * states, reads it back with glGetTexImage and prints how many of the 80
 * values differ. Build: cc swap_bytes_skip.c -lOSMesa. On Mesa 22.3.6:
 * 0 bad except "swap 1" together with a skip (44 and 20 bad). */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

static unsigned short value(int x, int y, int c) { return (unsigned short)(1000 * c + 37 * x + 4000 * y + 0x0101); }

static void run(int row_length, int skip_pixels, int skip_rows, int swap)
{
    static unsigned char mem[4096];
    unsigned short out[5 * 4 * 4];
    int x, y, c, bad = 0, stride = (row_length ? row_length : 5) * 8;
    memset(mem, 0xa5, sizeof mem);
    for (y = 0; y < 4; y++)
        for (x = 0; x < 5; x++)
            for (c = 0; c < 4; c++) {
                unsigned char *p = mem + (y + skip_rows) * stride + (x + skip_pixels) * 8 + c * 2;
                unsigned short v = value(x, y, c);
                unsigned short native = 0x0102;
                int little = *(unsigned char *)&native == 0x02;
                p[(little ^ swap) ? 0 : 1] = (unsigned char)(v & 255);
                p[(little ^ swap) ? 1 : 0] = (unsigned char)(v >> 8);
            }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, swap);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, 5, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT, mem);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, out);
    for (y = 0; y < 4; y++)
        for (x = 0; x < 5; x++)
            for (c = 0; c < 4; c++)
                bad += out[(y * 5 + x) * 4 + c] != value(x, y, c);
    printf("row_length %d skip_pixels %d skip_rows %d swap %d: %d bad\n", row_length, skip_pixels, skip_rows, swap, bad);
}

int main(void)
{
    static unsigned char buf[16 * 16 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16))
        return 2;
    run(0, 0, 0, 0);
    run(0, 0, 0, 1);
    run(7, 0, 0, 1);
    run(7, 2, 1, 0);
    run(7, 2, 1, 1);
    run(0, 0, 1, 1);
    OSMesaDestroyContext(ctx);
    return 0;
}
