/* Texture coordinates given per vertex inside display lists: a lit,
 * textured sphere compiled with GL_COMPILE and called twice (one call under
 * a different texture), a GLU sphere and disk (texture coordinates on)
 * compiled with GL_COMPILE_AND_EXECUTE, and a quad with two units
 * (glMultiTexCoord2f) called from a list twice. */
#include "tex_common.h"

#include <GL/glu.h>

int main(int argc, char **argv)
{
    static GLubyte checker[32 * 32 * 4], lightmap[16 * 16 * 4];
    const GLubyte c0[4] = {230, 200, 60, 255}, c1[4] = {40, 80, 200, 255};
    const GLubyte d0[4] = {250, 250, 250, 255}, d1[4] = {60, 60, 60, 255};
    GLuint tex[3];
    GLUquadric *q;
    int i;
    scene_begin(argc, argv, 240, 160);
    tex_checker(checker, 32, 32, 4, c0, c1);
    tex_checker(lightmap, 16, 16, 8, d0, d1);
    tex[0] = tex_new(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
    tex_upload_mipmaps(checker, 32, 32, GL_RGBA);
    tex[1] = tex_new(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, lightmap);
    tex[2] = tex_new(GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, lightmap);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.75, 0.75, -0.5, 0.5, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.0f);
    tex_lights();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

    glNewList(1, GL_COMPILE);
    tex_sphere(0.6f, 24, 16, 2.0f);
    glEndList();
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glPushMatrix();
    glTranslatef(-1.4f, 0.45f, 0.0f);
    glCallList(1);
    glTranslatef(0.0f, -1.0f, 0.0f);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glCallList(1);
    glPopMatrix();

    q = gluNewQuadric();
    gluQuadricTexture(q, GL_TRUE);
    gluQuadricNormals(q, GLU_SMOOTH);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glPushMatrix();
    glTranslatef(0.0f, 0.45f, 0.0f);
    glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
    glNewList(2, GL_COMPILE_AND_EXECUTE);
    gluSphere(q, 0.5, 20, 14);
    glEndList();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.0f, -0.6f, 0.0f);
    glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
    glNewList(3, GL_COMPILE_AND_EXECUTE);
    gluDisk(q, 0.1, 0.5, 20, 3);
    glEndList();
    glPopMatrix();
    gluDeleteQuadric(q);

    /* Two units from a list. */
    glDisable(GL_LIGHTING);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glNewList(4, GL_COMPILE);
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.9f, 0.9f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
    glVertex3f(0.8f, -0.9f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 3.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.0f);
    glVertex3f(1.9f, -0.9f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 3.0f, 3.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 1.0f);
    glVertex3f(1.9f, 0.9f, -0.5f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 3.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 1.0f);
    glVertex3f(0.8f, 0.9f, -0.5f);
    glEnd();
    glEndList();
    for (i = 0; i < 2; i++) {
        glCallList(4);
        glTranslatef(0.0f, 0.0f, -2.0f);
    }
    glDeleteLists(1, 4);
    glDeleteTextures(3, tex);
    return scene_end();
}
