/* The classic lit Bézier patch: a 4x4 MAP2_VERTEX_3 with GL_AUTO_NORMAL, glMapGrid2 and glEvalMesh2(GL_FILL), two lights, depth tested. */
#include "light_common.h"

/* The Red Book's bicubic patch, a little bent. */
static const GLfloat kPatch[4][4][3] = {
    {{-1.5f, -1.5f, 4.0f}, {-0.5f, -1.5f, 2.0f}, {0.5f, -1.5f, -1.0f}, {1.5f, -1.5f, 2.0f}},
    {{-1.5f, -0.5f, 1.0f}, {-0.5f, -0.5f, 3.0f}, {0.5f, -0.5f, 0.0f}, {1.5f, -0.5f, -1.0f}},
    {{-1.5f, 0.5f, 4.0f}, {-0.5f, 0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}, {1.5f, 0.5f, 4.0f}},
    {{-1.5f, 1.5f, -2.0f}, {-0.5f, 1.5f, -2.0f}, {0.5f, 1.5f, 0.0f}, {1.5f, 1.5f, -1.0f}}};

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 192, 192);
    light_ortho(2.6f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    light_all_black();
    light_model_ambient(0.1f, 0.1f, 0.12f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.7f, 0.5f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1.0f, 0.0f);
    light_fv(GL_LIGHT1, GL_DIFFUSE, 0.2f, 0.3f, 0.6f, 1.0f);
    light_fv(GL_LIGHT1, GL_POSITION, -2.0f, -1.0f, 3.0f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_AMBIENT, 0.3f, 0.3f, 0.3f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.9f, 0.6f, 0.4f, 1.0f);
    light_mat(GL_FRONT_AND_BACK, GL_SPECULAR, 0.6f, 0.6f, 0.6f, 1.0f);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    /* The mesh's strips wind clockwise where du x dv faces the viewer. */
    glFrontFace(GL_CW);

    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &kPatch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(20, 0.0f, 1.0f, 20, 0.0f, 1.0f);

    glTranslatef(0.0f, 0.0f, -2.0f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 20, 0, 20);
    scene_readpixels_check();
    return scene_end();
}
