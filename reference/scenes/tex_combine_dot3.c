/* GL_COMBINE (3x2 cells):
 *   0: GL_DOT3_RGB bump lighting: a normal map (dimples) dotted with the
 *      light vector, which each vertex carries in its primary colour
 *      (0.5 + 0.5 L, lighting off); unit 1 modulates GL_PREVIOUS by a base
 *      checker texture;
 *   1: GL_DOT3_RGBA, the same light vector, one unit;
 *   2: GL_INTERPOLATE between the texture and GL_CONSTANT by the primary
 *      colour's alpha (a glColor4f gradient), alpha GL_REPLACE;
 *   3: GL_ADD_SIGNED of the texture and the lit colour, GL_RGB_SCALE 2,
 *      alpha GL_MODULATE with GL_ALPHA_SCALE 2;
 *   4: GL_SUBTRACT: the lit colour minus (1 - texture colour), GL_RGB_SCALE
 *      2, alpha GL_REPLACE of (1 - texture alpha);
 *   5: crossbar: unit 0 GL_INTERPOLATE of GL_TEXTURE1 and GL_TEXTURE0 by
 *      GL_CONSTANT's alpha, unit 1 GL_MODULATE of GL_PREVIOUS and the lit
 *      colour. */
#include "tex_common.h"

static void combine(GLenum rgb, GLenum alpha)
{
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha);
}

static void arg(int i, GLenum src_rgb, GLenum op_rgb, GLenum src_a, GLenum op_a)
{
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, src_rgb);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, op_rgb);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, src_a);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, op_a);
}

/* A flat quad [-1,1]^2 in 16x16 cells, texcoords 0..2; with `light_vec`
 * each vertex's colour is the unit vector to a point light at (0.5, 0.6,
 * 0.7), encoded as 0.5 + 0.5 L, otherwise a colour/alpha gradient. */
static void quad(int light_vec)
{
    int i, j, k;
    glNormal3f(0.0f, 0.0f, 1.0f);
    for (j = 0; j < 16; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 16; i++)
            for (k = 1; k >= 0; k--) {
                float x = -1.0f + i / 8.0f, y = -1.0f + (j + k) / 8.0f;
                if (light_vec) {
                    float lx = 0.5f - x, ly = 0.6f - y, lz = 0.7f, l = (float)sqrt(lx * lx + ly * ly + lz * lz);
                    glColor3f(0.5f + 0.5f * lx / l, 0.5f + 0.5f * ly / l, 0.5f + 0.5f * lz / l);
                } else {
                    glColor4f(0.9f, 0.3f + 0.3f * y, 0.2f, 0.5f + 0.5f * x);
                }
                glMultiTexCoord2f(GL_TEXTURE0, x + 1.0f, y + 1.0f);
                glMultiTexCoord2f(GL_TEXTURE1, 0.5f * (x + 1.0f), 0.5f * (y + 1.0f));
                glVertex3f(x, y, 0.0f);
            }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    static GLubyte nmap[32 * 32 * 4], base[16 * 16 * 4];
    static const GLubyte c0[4] = { 240, 220, 160, 255 }, c1[4] = { 120, 170, 230, 90 };
    static const GLfloat constant[4] = { 0.3f, 0.9f, 0.4f, 0.35f };
    GLuint tn, tb;
    int x, y, c;
    scene_begin(argc, argv, 240, 160);
    /* normal map: a dome in each 8x8 block, flat (0,0,1) around it */
    for (y = 0; y < 32; y++)
        for (x = 0; x < 32; x++) {
            float dx = ((x % 8) - 3.5f) / 3.6f, dy = ((y % 8) - 3.5f) / 3.6f, d2 = dx * dx + dy * dy;
            float nx = 0.0f, ny = 0.0f, nz = 1.0f;
            if (d2 < 1.0f) {
                nz = (float)sqrt(1.0f - d2);
                nx = dx; ny = dy;
            }
            tex_put(nmap + 4 * (y * 32 + x), (int)(127.5f + 127.0f * nx), (int)(127.5f + 127.0f * ny),
                    (int)(127.5f + 127.0f * nz), 255 - 4 * x);
        }
    tex_checker(base, 16, 16, 4, c0, c1);
    glActiveTexture(GL_TEXTURE1);
    tb = tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_LINEAR, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
    glActiveTexture(GL_TEXTURE0);
    tn = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, nmap);

    for (c = 0; c < 6; c++) {
        light_cell(c, 3, 2, 80, 80);
        light_ortho(1.1f, 1.0f);
        glRotatef(15.0f, 0.3f, 1.0f, 0.0f);
        glActiveTexture(GL_TEXTURE0);
        glEnable(GL_TEXTURE_2D);
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
        glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1.0f);
        switch (c) {
        case 0:
        case 1:
            glDisable(GL_LIGHTING);
            glBindTexture(GL_TEXTURE_2D, tn);
            combine(c == 0 ? GL_DOT3_RGB : GL_DOT3_RGBA, GL_REPLACE);
            arg(0, GL_TEXTURE, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
            arg(1, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
            if (c == 0) {
                glActiveTexture(GL_TEXTURE1);
                glEnable(GL_TEXTURE_2D);
                combine(GL_MODULATE, GL_MODULATE);
                arg(0, GL_PREVIOUS, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_ALPHA);
                arg(1, GL_TEXTURE, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
            }
            quad(1);
            break;
        case 2:
            glDisable(GL_LIGHTING);
            glBindTexture(GL_TEXTURE_2D, tb);
            combine(GL_INTERPOLATE, GL_REPLACE);
            arg(0, GL_TEXTURE, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
            arg(1, GL_CONSTANT, GL_SRC_COLOR, GL_CONSTANT, GL_SRC_ALPHA);
            arg(2, GL_PRIMARY_COLOR, GL_SRC_ALPHA, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
            quad(0);
            break;
        case 3:
        case 4:
            tex_lights();
            /* dark enough that the doubled signed sum does not saturate */
            light_mat(GL_FRONT, GL_DIFFUSE, c == 3 ? 0.35f : 0.8f, c == 3 ? 0.3f : 0.6f, c == 3 ? 0.25f : 0.4f, 0.7f);
            light_model_ambient(0.05f, 0.05f, 0.05f, 1.0f);
            glBindTexture(GL_TEXTURE_2D, tb);
            glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0f);
            if (c == 3) {
                glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.0f);
                combine(GL_ADD_SIGNED, GL_MODULATE);
                arg(0, GL_TEXTURE, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
                arg(1, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
            } else {
                combine(GL_SUBTRACT, GL_REPLACE);
                arg(0, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_TEXTURE, GL_ONE_MINUS_SRC_ALPHA);
                arg(1, GL_TEXTURE, GL_ONE_MINUS_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
            }
            tex_sphere(1.0f, 32, 16, 2.0f);
            glDisable(GL_LIGHTING);
            break;
        case 5:
            tex_lights();
            glBindTexture(GL_TEXTURE_2D, tn);
            combine(GL_INTERPOLATE, GL_INTERPOLATE);
            arg(0, GL_TEXTURE1, GL_SRC_COLOR, GL_TEXTURE1, GL_SRC_ALPHA);
            arg(1, GL_TEXTURE0, GL_SRC_COLOR, GL_TEXTURE0, GL_SRC_ALPHA);
            arg(2, GL_CONSTANT, GL_SRC_ALPHA, GL_CONSTANT, GL_SRC_ALPHA);
            glActiveTexture(GL_TEXTURE1);
            glEnable(GL_TEXTURE_2D);
            combine(GL_MODULATE, GL_MODULATE);
            arg(0, GL_PREVIOUS, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_ALPHA);
            arg(1, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
            quad(0);
            glDisable(GL_LIGHTING);
            break;
        }
        glActiveTexture(GL_TEXTURE1);
        glDisable(GL_TEXTURE_2D);
        glActiveTexture(GL_TEXTURE0);
        glDisable(GL_TEXTURE_2D);
    }
    glDeleteTextures(1, &tn);
    glDeleteTextures(1, &tb);
    return scene_end();
}
