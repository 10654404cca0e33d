/* glMaterialfv inside glBegin/glEnd per vertex (diffuse, specular, emission, shininess), flat shading: the provoking (last) vertex's material and normal decide. */
#include "light_common.h"

int main(int argc, char **argv)
{
    scene_begin(argc, argv, 128, 128);
    light_ortho(1.05f, 1.0f);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    light_all_black();
    light_model_ambient(0.2f, 0.2f, 0.2f, 1.0f);
    light_fv(GL_LIGHT0, GL_DIFFUSE, 0.9f, 0.9f, 0.9f, 1.0f);
    light_fv(GL_LIGHT0, GL_SPECULAR, 1.0f, 1.0f, 1.0f, 1.0f);
    light_fv(GL_LIGHT0, GL_POSITION, -0.3f, 0.4f, 1.0f, 0.0f);
    light_mat(GL_FRONT, GL_AMBIENT, 0.3f, 0.3f, 0.3f, 1.0f);
    light_material_mesh();
    return scene_end();
}
