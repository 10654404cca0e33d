// glXUseXFont (GLX 1.4 §3.5): display list listBase + i draws glyph first + i
// of an X font with glBitmap, moving the raster position by the glyph's
// advance, as Mesa's xfonts.c lays glyphs out: the bitmap spans the glyph's
// ink (rbearing - lbearing by ascent + descent), its origin at
// (-lbearing, descent).
//
// glBitmap records into a list and moves the raster position, but does not
// draw its bits yet (issue 15): the lists exist, advance as they should, and
// draw once glBitmap does.
#include <X11/Xutil.h>

#include <vector>

#include "platform/glx_internal.h"
#include "platform/x11_error_trap.h"

namespace {

// The glyph's metrics, or null where the font has no such character.
const XCharStruct* glyphOf(const XFontStruct& fs, unsigned c) {
  const unsigned byte1 = c >> 8, byte2 = c & 0xff;
  if (byte1 < fs.min_byte1 || byte1 > fs.max_byte1 || byte2 < fs.min_char_or_byte2 ||
      byte2 > fs.max_char_or_byte2)
    return nullptr;
  if (!fs.per_char) return &fs.min_bounds;  // every glyph has the same metrics
  const unsigned columns = fs.max_char_or_byte2 - fs.min_char_or_byte2 + 1;
  const XCharStruct* ch = &fs.per_char[(byte1 - fs.min_byte1) * columns + (byte2 - fs.min_char_or_byte2)];
  if (ch->width == 0 && ch->lbearing == 0 && ch->rbearing == 0 && ch->ascent == 0 && ch->descent == 0)
    return nullptr;
  return ch;
}

// The glyph drawn into a 1-bit pixmap and read back, as glBitmap wants it:
// rows bottom to top, (width + 7) / 8 bytes each, most significant bit first.
std::vector<GLubyte> glyphBits(Display* dpy, Window root, Font font, unsigned c, const XCharStruct& ch,
                               int width, int height) {
  std::vector<GLubyte> bits(static_cast<size_t>((width + 7) / 8) * height, 0);
  Pixmap pixmap = XCreatePixmap(dpy, root, width, height, 1);
  XGCValues values;
  values.foreground = 0;
  values.background = 0;
  values.font = font;
  GC gc = XCreateGC(dpy, pixmap, GCForeground | GCBackground | GCFont, &values);
  XFillRectangle(dpy, pixmap, gc, 0, 0, width, height);
  XSetForeground(dpy, gc, 1);
  XChar2b glyph;
  glyph.byte1 = static_cast<unsigned char>(c >> 8);
  glyph.byte2 = static_cast<unsigned char>(c & 0xff);
  XDrawString16(dpy, pixmap, gc, -ch.lbearing, ch.ascent, &glyph, 1);
  if (XImage* image = XGetImage(dpy, pixmap, 0, 0, width, height, 1, XYPixmap)) {
    const int rowBytes = (width + 7) / 8;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (XGetPixel(image, x, y))
          bits[static_cast<size_t>(height - 1 - y) * rowBytes + x / 8] |= 0x80 >> (x % 8);
    XDestroyImage(image);
  }
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, pixmap);
  return bits;
}

}  // namespace

extern "C" {

GLAPI void APIENTRY glXUseXFont(Font font, int first, int count, int listBase) {
  __GLXcontextRec* ctx = glfixed::platform::glx::currentGlxContext();
  if (!ctx || count <= 0) return;  // GLXBadContextState without a current context
  Display* dpy = ctx->display;
  XFontStruct* fs = nullptr;
  {
    glfixed::platform::ErrorTrap trap(dpy);
    fs = XQueryFont(dpy, font);
    if (trap.failed() && fs) {
      XFreeFontInfo(nullptr, fs, 1);
      fs = nullptr;
    }
  }
  if (!fs) return;  // BadFont
  const Window root = RootWindow(dpy, ctx->config->screen);
  // The glyphs' bits as they are stored: tightly (the program's unpack
  // state is put back after; byte swapping and LSB_FIRST are always off in
  // this library).
  GLint rowLength = 0, skipRows = 0, skipPixels = 0, alignment = 4;
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
  glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  {
    glfixed::platform::ErrorTrap trap(dpy);
    for (int i = 0; i < count; ++i) {
      const unsigned c = static_cast<unsigned>(first + i);
      const XCharStruct* ch = glyphOf(*fs, c);
      glNewList(listBase + i, GL_COMPILE);
      if (ch) {
        const int width = ch->rbearing - ch->lbearing, height = ch->ascent + ch->descent;
        if (width > 0 && height > 0) {
          const std::vector<GLubyte> bits = glyphBits(dpy, root, font, c, *ch, width, height);
          glBitmap(width, height, static_cast<GLfloat>(-ch->lbearing), static_cast<GLfloat>(ch->descent),
                   static_cast<GLfloat>(ch->width), 0.0f, bits.data());
        } else {
          glBitmap(0, 0, 0.0f, 0.0f, static_cast<GLfloat>(ch->width), 0.0f, nullptr);
        }
      }
      glEndList();
    }
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  XFreeFontInfo(nullptr, fs, 1);
}

}  // extern "C"
