/* A cube map (tex_cube_map_faces, 8x8 faces) sampled with explicit 3D
 * texture coordinates (glTexCoord3f, no texgen): a lit cube whose corners
 * carry their own positions as (s, t, r), GL_NEAREST (left) and GL_LINEAR
 * (middle), and a lit sphere whose (s, t, r) is its normal scaled by
 * (1, 1.3, 0.7) (not unit: the face is chosen by the largest magnitude),
 * GL_LINEAR (right); GL_MODULATE. */
#include "tex_common.h"

static void cube(void)
{
    /* per face: normal, then four corners CCW from outside */
    static const float faces[6][5][3] = {
        { { 1, 0, 0 }, { 1, -1, 1 }, { 1, -1, -1 }, { 1, 1, -1 }, { 1, 1, 1 } },
        { { -1, 0, 0 }, { -1, -1, -1 }, { -1, -1, 1 }, { -1, 1, 1 }, { -1, 1, -1 } },
        { { 0, 1, 0 }, { -1, 1, 1 }, { 1, 1, 1 }, { 1, 1, -1 }, { -1, 1, -1 } },
        { { 0, -1, 0 }, { -1, -1, -1 }, { 1, -1, -1 }, { 1, -1, 1 }, { -1, -1, 1 } },
        { { 0, 0, 1 }, { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } },
        { { 0, 0, -1 }, { 1, -1, -1 }, { -1, -1, -1 }, { -1, 1, -1 }, { 1, 1, -1 } },
    };
    int f, v;
    glBegin(GL_QUADS);
    for (f = 0; f < 6; f++) {
        glNormal3fv(faces[f][0]);
        for (v = 1; v < 5; v++) {
            glTexCoord3fv(faces[f][v]);
            glVertex3fv(faces[f][v]);
        }
    }
    glEnd();
}

static void sphere(void)
{
    int i, j;
    for (i = 0; i < 20; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= 40; j++) {
            int k;
            for (k = 0; k < 2; k++) {
                double t = LIGHT_PI * (i + k) / 20, p = 2.0 * LIGHT_PI * j / 40;
                float x = (float)(sin(t) * cos(p)), y = (float)cos(t), z = (float)(-sin(t) * sin(p));
                glTexCoord3f(x, 1.3f * y, 0.7f * z);
                glNormal3f(x, y, z);
                glVertex3f(x, y, z);
            }
        }
        glEnd();
    }
}

int main(int argc, char **argv)
{
    GLuint names[2];
    int c;
    scene_begin(argc, argv, 336, 112);
    names[0] = tex_new(GL_TEXTURE_CUBE_MAP, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    tex_cube_map_faces(8);
    names[1] = tex_new(GL_TEXTURE_CUBE_MAP, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    tex_cube_map_faces(8);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_CUBE_MAP);
    tex_lights();
    light_model_ambient(0.45f, 0.45f, 0.45f, 1.0f);
    for (c = 0; c < 3; c++) {
        light_cell(c, 3, 1, 112, 112);
        light_frustum(0.3f, 1.0f, 1.0f, 20.0f);
        glBindTexture(GL_TEXTURE_CUBE_MAP, names[c == 0 ? 0 : 1]);
        glTranslatef(0.0f, 0.0f, -5.5f);
        glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(-35.0f + 15.0f * c, 0.0f, 1.0f, 0.0f);
        if (c == 2) {
            glScalef(1.3f, 1.3f, 1.3f);
            sphere();
        } else {
            cube();
        }
    }
    glDeleteTextures(2, names);
    return scene_end();
}
