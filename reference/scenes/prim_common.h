/* prim_common.h - shared geometry for the prim_* and provoking_* scenes.
 * Every vertex gets the next colour of a 12-entry palette, so flat shading
 * shows which vertex is the provoking one.  Coordinates are in a 128x128
 * pixel space (set up by prim_begin / prim_cell). */
#ifndef PRIM_COMMON_H
#define PRIM_COMMON_H
#include "scene.h"

static int prim_vcount;

static inline void prim_vertex(float x, float y)
{
    static const GLubyte pal[12][3] = {
        {255, 0, 0},   {0, 255, 0},   {0, 0, 255},   {255, 255, 0},
        {0, 255, 255}, {255, 0, 255}, {255, 128, 0}, {128, 0, 255},
        {0, 128, 64},  {255, 255, 255}, {96, 96, 96}, {200, 100, 150},
    };
    glColor3ubv(pal[prim_vcount++ % 12]);
    glVertex2f(x, y);
}

/* Standard set-up: 128x128 buffer, one unit = one pixel. */
static inline void prim_begin(int argc, char **argv, GLenum shade)
{
    scene_begin(argc, argv, 128, 128);
    scene_ortho_pixels();
    glShadeModel(shade);
    prim_vcount = 0;
}

/* Cell i of a 3x2 grid of 128x128 cells (buffer 384x256). */
static inline void prim_cell(int i)
{
    glViewport((i % 3) * 128, (i / 3) * 128, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 128, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static inline void draw_triangles(void)
{
    glBegin(GL_TRIANGLES);
    prim_vertex(4.0f, 4.0f);    prim_vertex(60.0f, 10.5f);  prim_vertex(20.25f, 58.0f);  /* CCW */
    prim_vertex(70.0f, 8.0f);   prim_vertex(84.5f, 60.0f);  prim_vertex(124.0f, 20.0f);  /* CW */
    prim_vertex(8.0f, 70.0f);   prim_vertex(120.0f, 72.3f); prim_vertex(10.0f, 78.0f);   /* thin */
    prim_vertex(64.0f, 82.0f);  prim_vertex(124.0f, 124.0f); prim_vertex(30.0f, 122.7f);
    prim_vertex(4.0f, 90.0f);   prim_vertex(20.0f, 91.0f);  /* incomplete: ignored */
    glEnd();
}

static inline void draw_triangle_strip(void)
{
    int i;
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 8; i++)
        prim_vertex(6.0f + i * 16.5f, (i & 1) ? 60.0f : 8.0f + i * 1.5f);
    glEnd();
    glBegin(GL_TRIANGLE_STRIP);   /* bent strip, 7 vertices */
    prim_vertex(10.0f, 70.0f);  prim_vertex(14.0f, 120.0f); prim_vertex(40.0f, 75.0f);
    prim_vertex(52.0f, 118.0f); prim_vertex(80.0f, 90.0f);  prim_vertex(110.0f, 124.0f);
    prim_vertex(122.0f, 72.0f);
    glEnd();
}

static inline void draw_triangle_fan(void)
{
    int i;
    glBegin(GL_TRIANGLE_FAN);
    prim_vertex(40.0f, 40.0f);
    for (i = 0; i < 7; i++) {
        static const float p[7][2] = {{76, 40}, {70, 70}, {40, 76.5f}, {10, 70},
                                      {4, 40}, {10, 10}, {40, 4}};
        prim_vertex(p[i][0], p[i][1]);
    }
    glEnd();
    glBegin(GL_TRIANGLE_FAN);   /* fan whose centre is a corner */
    prim_vertex(124.0f, 124.0f); prim_vertex(70.0f, 120.0f); prim_vertex(66.0f, 90.0f);
    prim_vertex(80.0f, 70.0f);   prim_vertex(100.0f, 60.0f); prim_vertex(122.0f, 58.0f);
    glEnd();
}

static inline void draw_quads(void)
{
    glBegin(GL_QUADS);
    prim_vertex(4.0f, 4.0f);    prim_vertex(60.0f, 4.0f);   prim_vertex(60.0f, 60.0f);  prim_vertex(4.0f, 60.0f);
    prim_vertex(70.0f, 10.0f);  prim_vertex(120.0f, 4.5f);  prim_vertex(110.0f, 58.0f); prim_vertex(76.0f, 50.0f);
    prim_vertex(10.0f, 70.0f);  prim_vertex(30.0f, 124.0f); prim_vertex(60.0f, 120.0f); prim_vertex(62.0f, 80.0f); /* CW */
    prim_vertex(70.0f, 70.0f);  prim_vertex(124.0f, 75.0f); prim_vertex(118.0f, 110.0f); prim_vertex(90.0f, 124.0f);
    prim_vertex(1.0f, 1.0f);    prim_vertex(3.0f, 1.0f);    prim_vertex(3.0f, 3.0f);    /* incomplete */
    glEnd();
}

static inline void draw_quad_strip(void)
{
    int i;
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 5; i++) {
        prim_vertex(6.0f + i * 29.0f, 6.0f + (i & 1) * 8.0f);
        prim_vertex(10.0f + i * 28.0f, 56.0f - (i & 1) * 5.5f);
    }
    glEnd();
    glBegin(GL_QUAD_STRIP);   /* 7 vertices: last one ignored */
    prim_vertex(10.0f, 70.0f);  prim_vertex(10.0f, 122.0f); prim_vertex(50.0f, 72.0f);
    prim_vertex(44.0f, 110.0f); prim_vertex(120.0f, 66.0f); prim_vertex(96.0f, 124.0f);
    prim_vertex(124.0f, 124.0f);
    glEnd();
}

static inline void draw_polygon(void)
{
    int i;
    glBegin(GL_POLYGON);   /* convex hexagon */
    for (i = 0; i < 6; i++) {
        static const float p[6][2] = {{30, 4}, {70, 8}, {84, 40}, {66, 70}, {24, 66}, {6, 34}};
        prim_vertex(p[i][0], p[i][1]);
    }
    glEnd();
    glBegin(GL_POLYGON);   /* clockwise pentagon */
    prim_vertex(90.0f, 80.0f);  prim_vertex(80.0f, 110.0f); prim_vertex(104.0f, 124.0f);
    prim_vertex(124.0f, 104.0f); prim_vertex(118.0f, 78.0f);
    glEnd();
    glBegin(GL_POLYGON);   /* triangle as a polygon */
    prim_vertex(90.0f, 10.0f); prim_vertex(124.0f, 12.0f); prim_vertex(110.0f, 60.0f);
    glEnd();
}

#endif
