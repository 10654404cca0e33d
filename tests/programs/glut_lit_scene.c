/*
 * glut_lit_scene - a freeglut program of the kind real legacy programs are: a
 * double-buffered RGB + depth window, a teapot, a torus and a sphere lit by
 * two lights (one directional, one spot), specular materials, smooth
 * shading, depth test. It draws FRAMES frames, turning the objects a little
 * each frame (by frame number, never by the clock), and after the last swap
 * reads the window back from the X server with XGetImage and writes it.
 *
 * usage: glut_lit_scene OUT_PREFIX [FRAMES] [--resize] [--rss]
 *   writes OUT_PREFIX.glfx (the dump format of reference/scenes/scene.h);
 *   --resize: after half the frames, glutReshapeWindow(256, 200); the frames
 *   after it are counted once the reshape callback has the new size, and the
 *   picture is read at that size (the surface must follow its window);
 *   --rss prints the memory use every 100 frames and at the end.
 * Exit status: 0 drawn and written, 1 usage, 2 failure (message on stderr).
 */
#include <GL/freeglut.h>
#include <GL/glx.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "program_common.h"
#include "program_x11.h"

enum { WIDTH = 320, HEIGHT = 240, RESIZED_WIDTH = 256, RESIZED_HEIGHT = 200 };

static struct {
    const char *prefix;
    int frames, frame, rss;
    int resize;        /* --resize: 1 asked, 2 asked of the window */
    int width, height; /* from the reshape callback */
    int status;
} P = {NULL, 10, 0, 0, 0, WIDTH, HEIGHT, 2};

static void reshape(int width, int height)
{
    P.width = width;
    P.height = height;
    glutPostRedisplay();
}

/* The size the window has at the last frame. */
static int final_width(void) { return P.resize ? RESIZED_WIDTH : WIDTH; }
static int final_height(void) { return P.resize ? RESIZED_HEIGHT : HEIGHT; }

/* Reads the window back (after the last swap) and writes the picture. */
static int finish(void)
{
    glFinish();
    Display *dpy = glXGetCurrentDisplay();
    const GLXDrawable drawable = glXGetCurrentDrawable();
    if (!dpy || !drawable) {
        fprintf(stderr, "glut_lit_scene: glXGetCurrentDisplay / glXGetCurrentDrawable gave %p / 0x%lx\n",
                (void *)dpy, (unsigned long)drawable);
        return -1;
    }
    const int width = final_width(), height = final_height();
    int w = 0, h = 0;
    if (program_window_size(dpy, drawable, &w, &h) != 0 || w != width || h != height) {
        fprintf(stderr, "glut_lit_scene: the window is %dx%d, not %dx%d\n", w, h, width, height);
        return -1;
    }
    unsigned char *rgba = malloc((size_t)width * height * 4);
    if (!rgba) return -1;
    int rc = program_read_window(dpy, drawable, width, height, rgba);
    if (rc == 0) rc = program_write_dump(P.prefix, width, height, rgba, 3, P.frames);
    if (rc == 0) printf("covered pixels: %ld of %d\n", program_covered_pixels(width, height, rgba),
                        width * height);
    free(rgba);
    return rc;
}

static void display(void)
{
    /* --resize: ask at half the frames, then draw only once the reshape
     * callback has the new size, so the frame count stays deterministic. */
    if (P.resize == 1 && P.frame == P.frames / 2) {
        glutReshapeWindow(RESIZED_WIDTH, RESIZED_HEIGHT);
        P.resize = 2;
    }
    if (P.resize == 2 && (P.width != RESIZED_WIDTH || P.height != RESIZED_HEIGHT)) return;
    const float a = program_angle(P.frame, 3.0f);
    program_clear();
    program_view(P.width, P.height, P.frame);

    glPushMatrix();
    glTranslatef(-0.2f, 0.15f, 0.0f);
    glRotatef(a, 0.0f, 1.0f, 0.0f);
    glRotatef(10.0f, 1.0f, 0.0f, 0.0f);
    program_material(0.8f, 0.6f, 0.2f, 50.0f);
    glutSolidTeapot(0.75);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(1.55f, -0.25f, -0.3f);
    glRotatef(a, 1.0f, 0.4f, 0.0f);
    program_material(0.2f, 0.7f, 0.35f, 30.0f);
    glutSolidTorus(0.15, 0.45, 16, 32);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(-1.6f, -0.35f, 0.4f);
    glRotatef(-a, 0.0f, 0.0f, 1.0f);
    program_material(0.3f, 0.4f, 0.9f, 80.0f);
    glutSolidSphere(0.5, 24, 16);
    glPopMatrix();

    glutSwapBuffers();
    P.frame++;
    if (P.rss && (P.frame % 100 == 0 || P.frame == P.frames)) program_report_rss(P.frame);
    if (P.frame >= P.frames) {
        P.status = finish() == 0 ? 0 : 2;
        glutLeaveMainLoop();
        return;
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    int positional = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--rss") == 0) {
            P.rss = 1;
        } else if (strcmp(argv[i], "--resize") == 0) {
            P.resize = 1;
        } else if (positional == 0) {
            P.prefix = argv[i];
            positional++;
        } else if (positional == 1 && (P.frames = program_frames_arg(argv[i], 10)) > 0) {
            positional++;
        } else {
            positional = -1;
            break;
        }
    }
    if (positional < 1) {
        fprintf(stderr, "usage: glut_lit_scene OUT_PREFIX [FRAMES] [--resize] [--rss]\n");
        return 1;
    }
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowPosition(0, 0);
    glutInitWindowSize(WIDTH, HEIGHT);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    if (glutCreateWindow("glut_lit_scene") <= 0) {
        fprintf(stderr, "glut_lit_scene: glutCreateWindow failed\n");
        return 2;
    }
    if (program_print_renderer() != 0) return 2;
    program_lights_setup();
    glutReshapeFunc(reshape);
    glutDisplayFunc(display);
    glutMainLoop();
    return P.status;
}
