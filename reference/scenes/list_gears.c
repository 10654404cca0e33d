/* Display lists: three lit gears (quad strips and quads, flat faces and a
 * smooth inner cylinder, normals given inside and outside glBegin/glEnd),
 * each compiled into a list once and replayed over several frames with
 * glRotate between the calls, as a gears demo draws them. */
#include <math.h>

#include "scene.h"

static void gear(float inner, float outer, float width, int teeth, float depth)
{
    const float r0 = inner, r1 = outer - depth / 2, r2 = outer + depth / 2;
    const float step = 2.0f * (float)M_PI / teeth, da = step / 4;
    const float hw = width * 0.5f;
    int i, side;

    glShadeModel(GL_FLAT);
    for (side = 0; side < 2; side++) {  /* front (z = +hw), then back */
        const float z = side ? -hw : hw;
        glNormal3f(0, 0, side ? -1.0f : 1.0f);
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= teeth; i++) {
            const float a = i * step;
            if (side) {
                glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
                glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
            } else {
                glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
                glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
            }
            if (i < teeth) {
                const float b = a + 3 * da;
                if (side) {
                    glVertex3f(r1 * cosf(b), r1 * sinf(b), z);
                    glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
                } else {
                    glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
                    glVertex3f(r1 * cosf(b), r1 * sinf(b), z);
                }
            }
        }
        glEnd();
        glBegin(GL_QUADS);  /* the teeth's faces */
        for (i = 0; i < teeth; i++) {
            const float a = i * step;
            float x[4], y[4];
            int k;
            x[0] = r1 * cosf(a);          y[0] = r1 * sinf(a);
            x[1] = r2 * cosf(a + da);     y[1] = r2 * sinf(a + da);
            x[2] = r2 * cosf(a + 2 * da); y[2] = r2 * sinf(a + 2 * da);
            x[3] = r1 * cosf(a + 3 * da); y[3] = r1 * sinf(a + 3 * da);
            for (k = 0; k < 4; k++) {
                const int j = side ? 3 - k : k;
                glVertex3f(x[j], y[j], z);
            }
        }
        glEnd();
    }

    /* The outward faces of the teeth: a normal per face, inside glBegin/glEnd. */
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < teeth; i++) {
        const float a = i * step;
        float u, v, len;
        glVertex3f(r1 * cosf(a), r1 * sinf(a), hw);
        glVertex3f(r1 * cosf(a), r1 * sinf(a), -hw);
        u = r2 * cosf(a + da) - r1 * cosf(a);
        v = r2 * sinf(a + da) - r1 * sinf(a);
        len = sqrtf(u * u + v * v);
        u /= len; v /= len;
        glNormal3f(v, -u, 0);
        glVertex3f(r2 * cosf(a + da), r2 * sinf(a + da), hw);
        glVertex3f(r2 * cosf(a + da), r2 * sinf(a + da), -hw);
        glNormal3f(cosf(a), sinf(a), 0);
        glVertex3f(r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), hw);
        glVertex3f(r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), -hw);
        u = r1 * cosf(a + 3 * da) - r2 * cosf(a + 2 * da);
        v = r1 * sinf(a + 3 * da) - r2 * sinf(a + 2 * da);
        glNormal3f(v, -u, 0);
        glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), hw);
        glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), -hw);
        glNormal3f(cosf(a), sinf(a), 0);
    }
    glVertex3f(r1, 0, hw);
    glVertex3f(r1, 0, -hw);
    glEnd();

    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUAD_STRIP);  /* the inner cylinder */
    for (i = 0; i <= teeth; i++) {
        const float a = i * step;
        glNormal3f(-cosf(a), -sinf(a), 0);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), -hw);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), hw);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLfloat pos[4] = {5, 5, 10, 0};
    static const GLfloat red[4] = {0.8f, 0.1f, 0, 1}, green[4] = {0, 0.8f, 0.2f, 1}, blue[4] = {0.2f, 0.2f, 1, 1};
    GLuint gears;
    int frame;
    scene_begin(argc, argv, 240, 200);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);

    gears = glGenLists(3);
    glNewList(gears, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    gear(1.0f, 4.0f, 1.0f, 20, 0.7f);
    glEndList();
    glNewList(gears + 1, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
    gear(0.5f, 2.0f, 2.0f, 10, 0.7f);
    glEndList();
    glNewList(gears + 2, GL_COMPILE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    gear(1.3f, 2.0f, 0.5f, 10, 0.7f);
    glEndList();
    glEnable(GL_NORMALIZE);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.2, 1.2, -1.0, 1.0, 5.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -40);

    for (frame = 0; frame < 4; frame++) {
        const float angle = 7.0f + 11.0f * frame;
        scene_clear();
        glPushMatrix();
        glRotatef(20.0f + frame, 1, 0, 0);
        glRotatef(30.0f, 0, 1, 0);
        glRotatef(0.0f, 0, 0, 1);
        glPushMatrix();
        glTranslatef(-3, -2, 0);
        glRotatef(angle, 0, 0, 1);
        glCallList(gears);
        glPopMatrix();
        glPushMatrix();
        glTranslatef(3.1f, -2, 0);
        glRotatef(-2 * angle - 9, 0, 0, 1);
        glCallList(gears + 1);
        glPopMatrix();
        glPushMatrix();
        glTranslatef(-3.1f, 4.2f, 0);
        glRotatef(-2 * angle - 25, 0, 0, 1);
        glCallList(gears + 2);
        glPopMatrix();
        glPopMatrix();
    }
    return scene_end();
}
