/* polygon_offset_common.h - coplanar lit surfaces in perspective, drawn twice,
 * the second time with glPolygonOffset: which one wins is decided by the
 * offset's last bit (units scaled by the depth buffer's precision, the slope
 * factor from each triangle's z gradient). Used by polygon_offset_fill
 * (24-bit depth) and polygon_offset_fill16 (16-bit). */
#ifndef POLYGON_OFFSET_COMMON_H
#define POLYGON_OFFSET_COMMON_H
#include "scene.h"

/* A lit, tilted strip of quads at row `row` of the view, normals per vertex. */
static inline void offset_strip(float y, float tilt, float bend)
{
    int i;
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= 8; i++) {
        float x = -1.6f + 0.4f * (float)i;
        float z = -4.0f + tilt * x + bend * x * x;
        glNormal3f(-tilt, 0.3f, 1.0f);
        glVertex3f(x, y, z);
        glVertex3f(x, y + 0.3f, z - 0.2f);
    }
    glEnd();
}

static inline void offset_scene(int argc, char **argv, int depth_bits)
{
    /* factor, units, depth func of the second pass */
    static const struct { float factor, units; GLenum func; } rows[] = {
        {0.0f, -1.0f, GL_LESS},   {-1.0f, 0.0f, GL_LESS},  {-1.0f, -1.0f, GL_LESS},
        {1.0f, 1.0f, GL_LESS},    {0.0f, 0.25f, GL_EQUAL}, {0.0f, 0.5f, GL_LEQUAL},
        {0.37f, 0.0f, GL_LEQUAL}, {-0.5f, 3.0f, GL_LESS},  {2.5f, -7.0f, GL_GEQUAL},
        {0.0f, 1e7f, GL_LESS},
    };
    static const float red[4] = {0.9f, 0.2f, 0.1f, 1}, blue[4] = {0.1f, 0.3f, 0.9f, 1};
    static const float light[4] = {0.3f, 0.6f, 1.0f, 0};
    scene_options o = {128, 160, OSMESA_RGBA, depth_bits, 1, 0};
    unsigned i;
    scene_begin_ext(argc, argv, &o);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1.25, 1.25, 2, 9);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_COLOR_MATERIAL);
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        float y = -2.3f + 0.46f * (float)i;
        float tilt = -0.9f + 0.2f * (float)i, bend = (i & 1) ? 0.15f : -0.1f;
        glDepthFunc(GL_LESS);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glColor4fv(red);
        offset_strip(y, tilt, bend);
        glDepthFunc(rows[i].func);
        glPolygonOffset(rows[i].factor, rows[i].units);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glColor4fv(blue);
        offset_strip(y, tilt, bend);
    }
    /* Offset with only GL_POLYGON_OFFSET_LINE on: Mesa offsets filled
     * polygons too (MESA_FACTS.md, "Polygons"). */
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_LESS);
    glColor4fv(red);
    offset_strip(2.3f, 0.3f, 0.0f);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(0.0f, -4.0f);
    glColor4f(0.2f, 0.9f, 0.2f, 1);
    offset_strip(2.3f, 0.3f, 0.0f);
    glDisable(GL_POLYGON_OFFSET_LINE);
}
#endif
