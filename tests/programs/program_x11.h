/*
 * program_x11.h - reads an X11 window back with XGetImage, for the window
 * programs (glut_lit_scene, egl_window_scene). What the X server shows is
 * what is compared: the window's contents after the swap reached the server,
 * not the GL's idea of its front buffer.
 */
#ifndef GLFX_PROGRAM_X11_H
#define GLFX_PROGRAM_X11_H

#include <X11/Xlib.h>

#ifdef __cplusplus
extern "C" {
#endif

/* XSync(dpy), then XGetImage(window, 0, 0, width, height, ZPixmap) decoded
 * with the image's channel masks into rgba (width*height*4 bytes, top row
 * first, alpha 255). Returns 0, or prints why and returns -1. */
int program_read_window(Display *dpy, Window window, int width, int height, unsigned char *rgba);

/* The window's size as the server has it (XGetGeometry), -1 on failure. */
int program_window_size(Display *dpy, Window window, int *width, int *height);

#ifdef __cplusplus
}
#endif
#endif
