/* program_x11.c - XGetImage read-back of a window (see program_x11.h). */
#include "program_x11.h"

#include <X11/Xutil.h>
#include <stdio.h>

/* Scales a masked channel value to 8 bits (masks of 8 bits are exact). */
static unsigned char channel(unsigned long pixel, unsigned long mask)
{
    if (!mask) return 0;
    int shift = 0, bits = 0;
    while (!((mask >> shift) & 1)) shift++;
    while ((mask >> (shift + bits)) & 1) bits++;
    const unsigned long v = (pixel & mask) >> shift;
    const unsigned long max = (1ul << bits) - 1;
    return (unsigned char)((v * 255 + max / 2) / max);
}

int program_read_window(Display *dpy, Window window, int width, int height, unsigned char *rgba)
{
    XSync(dpy, False);
    XImage *image = XGetImage(dpy, window, 0, 0, (unsigned)width, (unsigned)height, AllPlanes, ZPixmap);
    if (!image) {
        fprintf(stderr, "XGetImage of window 0x%lx (%dx%d) failed\n", (unsigned long)window, width,
                height);
        return -1;
    }
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const unsigned long pixel = XGetPixel(image, x, y);
            unsigned char *p = &rgba[((size_t)y * (size_t)width + (size_t)x) * 4];
            p[0] = channel(pixel, image->red_mask);
            p[1] = channel(pixel, image->green_mask);
            p[2] = channel(pixel, image->blue_mask);
            p[3] = 255;
        }
    XDestroyImage(image);
    return 0;
}

int program_window_size(Display *dpy, Window window, int *width, int *height)
{
    Window root;
    int x, y;
    unsigned w, h, border, depth;
    if (!XGetGeometry(dpy, window, &root, &x, &y, &w, &h, &border, &depth)) return -1;
    *width = (int)w;
    *height = (int)h;
    return 0;
}
