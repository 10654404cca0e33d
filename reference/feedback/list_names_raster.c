/*
 * list_names_raster: the name stack, glPassThrough, the raster position and
 * array draws compiled into display lists (§5.4), replayed in GL_SELECT and
 * GL_FEEDBACK: glInitNames, glPushName, glLoadName, glPopName around
 * primitives in a list; glRasterPos in several forms, glBitmap (moving the
 * raster position) and glPassThrough in a list; glDrawArrays and
 * glDrawElements in a list whose arrays changed before the replay (the
 * feedback shows the compiled vertices); a name-stack error compiled into a
 * list (raised at replay); GL_COMPILE_AND_EXECUTE while in GL_FEEDBACK; and
 * glRenderMode, glSelectBuffer, glFeedbackBuffer inside glNewList, which are
 * executed at once (§5.4).
 */
#include "fb_common.h"

enum { W = 64, H = 48 };
static GLuint sel[512];
static GLfloat fb[2048];
static GLfloat verts[8][3] = {{-0.8f, -0.8f, -0.5f}, {-0.2f, -0.7f, -0.4f}, {-0.5f, -0.1f, -0.3f},
                              {0.1f, 0.1f, -0.6f},   {0.7f, 0.2f, -0.2f},   {0.4f, 0.8f, -0.7f},
                              {-0.6f, 0.5f, -0.1f},  {0.0f, -0.3f, -0.9f}};
static GLfloat colors[8][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1},
                               {0, 1, 1, 1}, {1, 0, 1, 1}, {0.5f, 0.5f, 0.5f, 1}, {0.25f, 0.75f, 0.5f, 1}};
static const GLubyte bits[8] = {0xff, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xff};
enum { NAMES = 1, RASTER, ARRAYS, BAD_NAME, EXEC };

static void tri(float x, float y, float z) {
    glBegin(GL_TRIANGLES);
    glVertex3f(x - 0.2f, y - 0.2f, z);
    glVertex3f(x + 0.2f, y - 0.2f, z);
    glVertex3f(x, y + 0.2f, z - 0.1f);
    glEnd();
}

int main(void) {
    static const GLubyte idx[6] = {7, 6, 5, 4, 3, 2};
    fb_begin(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, 0, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glNewList(NAMES, GL_COMPILE);
    glInitNames();
    glPushName(1);
    tri(-0.5f, -0.5f, -0.2f);
    glPushName(11);
    tri(0.5f, -0.5f, -0.4f);
    glLoadName(12);
    tri(0.5f, 0.5f, -0.6f);
    glPopName();
    glLoadName(2);
    tri(-0.5f, 0.5f, -0.8f);
    glPopName();
    tri(0.0f, 0.0f, -0.5f);
    glEndList();
    fb_error("compile NAMES");

    glNewList(RASTER, GL_COMPILE);
    glPassThrough(1.0f);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glRasterPos2f(-0.5f, 0.25f);
    glBitmap(8, 8, 0, 0, 3, -2, bits);
    glPassThrough(2.0f);
    glRasterPos3i(0, 0, 0);
    glBitmap(0, 0, 0, 0, 5.5f, 1.25f, bits);
    glBitmap(8, 8, 1, 1, 0, 0, bits);
    glRasterPos4d(0.25, -0.25, -0.5, 1.0);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, bits);
    glRasterPos3sv((const GLshort[]){2, 0, 0}); /* outside: invalid */
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    glPassThrough(3.0f);
    glRasterPos2fv((const GLfloat[]){0.5f, 0.5f});
    glCopyPixels(0, 0, 4, 4, GL_COLOR);
    glEndList();
    fb_error("compile RASTER");

    glVertexPointer(3, GL_FLOAT, 0, verts);
    glColorPointer(4, GL_FLOAT, 0, colors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glNewList(ARRAYS, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glPassThrough(4.0f);
    glDrawElements(GL_TRIANGLE_STRIP, 6, GL_UNSIGNED_BYTE, idx);
    glPassThrough(4.5f); /* without it Mesa crashes replaying the list (MESA_FACTS) */
    glDrawArrays(GL_LINES, 4, 4);
    glPassThrough(4.75f);
    glDrawArrays(GL_POINTS, 1, 2);
    glEndList();
    fb_error("compile ARRAYS");
    for (int i = 0; i < 8; ++i) { verts[i][0] = 0; verts[i][1] = 0; colors[i][1] = 0.125f; }

    glNewList(BAD_NAME, GL_COMPILE);
    glInitNames();
    glLoadName(5); /* empty stack: GL_INVALID_OPERATION when replayed in GL_SELECT */
    glPopName();   /* GL_STACK_UNDERFLOW */
    glEndList();
    fb_error("compile BAD_NAME");

    /* selection */
    glSelectBuffer(512, sel);
    glRenderMode(GL_SELECT);
    glCallList(NAMES);
    fb_error("select NAMES");
    fb_print_select("names", glRenderMode(GL_RENDER), sel, 512);
    glRenderMode(GL_SELECT);
    glCallList(BAD_NAME);
    fb_error("select BAD_NAME (load)");
    fb_error("select BAD_NAME (pop)");
    glPushName(9);
    glCallList(ARRAYS);
    fb_print_select("arrays", glRenderMode(GL_RENDER), sel, 512);

    /* feedback */
    glFeedbackBuffer(2048, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glCallList(RASTER);
    fb_error("feedback RASTER");
    glCallList(ARRAYS);
    glCallList(NAMES); /* names are ignored in GL_FEEDBACK */
    fb_print_feedback("raster, arrays, names", GL_3D_COLOR, glRenderMode(GL_RENDER), fb, 2048);

    /* GL_COMPILE_AND_EXECUTE in GL_FEEDBACK; glRenderMode and
     * glFeedbackBuffer in a list run at once */
    glFeedbackBuffer(2048, GL_4D_COLOR_TEXTURE, fb);
    glNewList(EXEC, GL_COMPILE_AND_EXECUTE);
    glRenderMode(GL_FEEDBACK);
    glPassThrough(5.0f);
    glRasterPos2i(0, 0);
    glBitmap(8, 8, 0, 0, 1, 1, bits);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndList();
    fb_print_feedback("compile and execute", GL_4D_COLOR_TEXTURE, glRenderMode(GL_RENDER), fb, 2048);
    glRenderMode(GL_FEEDBACK);
    glCallList(EXEC);
    fb_print_feedback("replayed", GL_4D_COLOR_TEXTURE, glRenderMode(GL_RENDER), fb, 2048);
    return fb_end();
}
