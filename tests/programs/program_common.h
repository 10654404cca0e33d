/*
 * program_common.h - what the real programs of tests/programs/ share: the
 * lit scene they draw, the picture they write, and the memory they report.
 *
 * The programs are ordinary C programs built against the system's headers and
 * linked against the system's libGL / libEGL / libglut, so the same binary
 * runs on Mesa and, with LD_LIBRARY_PATH=<build>/dropin, on libglfixed.
 *
 * Picture file: <prefix>.glfx in the reference scenes' dump format
 * (reference/scenes/scene.h), so reference/glfx_compare compares it with the
 * fidelity bar. The programs clear to the KEY colour (3, 5, 7) and the lit
 * scene has a global ambient term that keeps every lit pixel brighter than
 * that in blue, so "covered" means "drawn" in a window image too, which has
 * no alpha and no depth to tell.
 */
#ifndef GLFX_PROGRAM_COMMON_H
#define GLFX_PROGRAM_COMMON_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define PROGRAM_KEY_R 3
#define PROGRAM_KEY_G 5
#define PROGRAM_KEY_B 7

/* glClearColor(KEY) + glClearDepth(1) + glClear(COLOR | DEPTH). */
void program_clear(void);

/* The fixed-function state of the lit scene: two lights (light 0 directional
 * white, light 1 a warm spot light with attenuation, both with specular),
 * the global ambient, smooth shading, depth test (GL_LESS), back-face culling
 * off. Call once after the context is current. */
void program_lights_setup(void);

/* Projection for a width x height viewport (glViewport, glFrustum) and the
 * view matrix, and the light positions for `frame` (they are given in eye
 * space after the view matrix, so they move with the camera). Leaves the
 * matrix mode at GL_MODELVIEW with the view matrix loaded. */
void program_view(int width, int height, int frame);

/* A material: ambient and diffuse = rgb, specular white-ish, shininess. */
void program_material(float r, float g, float b, float shininess);

/* The angle (degrees) an object turns by at `frame`: deterministic, no clock. */
float program_angle(int frame, float degrees_per_frame);

/* Hand-made meshes drawn with glBegin/glEnd (quad strips with normals), for
 * the EGL programs, which have no GLUT: a sphere of `radius` centred at the
 * origin and a torus around the z axis. */
void program_sphere(float radius, int slices, int stacks);
void program_torus(float inner_radius, float outer_radius, int sides, int rings);
/* A mesh of the same sphere drawn from client arrays with glDrawElements
 * (GL_TRIANGLES, GL_UNSIGNED_SHORT), so a program uses both paths. */
void program_sphere_arrays(float radius, int slices, int stacks);

/* The whole EGL scene for one frame: clear, view, two spheres, a torus and an
 * arrays sphere, each turning. */
void program_draw_egl_scene(int width, int height, int frame);

/* Writes <prefix>.glfx: width x height RGBA8 pixels, top row first,
 * coverage_channels 3 (RGB, a window: alpha ignored) or 4; no depth.
 * `frames` and the GL error go into the info line. Returns 0, or prints
 * why and returns -1. */
int program_write_dump(const char *prefix, int width, int height, const unsigned char *rgba,
                       int coverage_channels, int frames);

/* Counts the pixels (RGBA8) that are not the KEY colour in R, G, B. */
long program_covered_pixels(int width, int height, const unsigned char *rgba);

/* Prints "GL_RENDERER: ..." and "GL_VERSION: ..." to stdout (the harness
 * checks which library drew). Returns -1 when glGetString gives NULL. */
int program_print_renderer(void);

/* A field of /proc/self/status in kB ("VmHWM", "VmRSS"), -1 if unreadable. */
long program_status_kb(const char *field);

/* Reports memory at a frame when asked with --rss: prints
 * "rss frame=<n> VmRSS=<kB> VmHWM=<kB>" to stdout. */
void program_report_rss(int frame);

/* Parses "<prefix> [frames] [options]": returns the frame count (default
 * `default_frames`), or -1 for a bad count. */
int program_frames_arg(const char *arg, int default_frames);

#ifdef __cplusplus
}
#endif
#endif
