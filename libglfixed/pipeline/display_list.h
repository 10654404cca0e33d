// Display lists (GL 2.1 §5.4), per context.
//
// A list is a sequence of commands. Every listable entry point records itself
// with one line (api/list_record.h): the command is stored as a call of the
// same entry point with its arguments by value, so a replay runs exactly the
// code an immediate call runs. Vertices between glBegin and glEnd are not
// stored as calls: they become a VertexNode, built as Mesa's vbo save module
// builds its vertex lists (vbo_save_api.c), because which primitives share a
// draw decides llvmpipe's pixels (primitive/merge.h):
//   - a node holds the glBegin/glEnd pairs between two other commands (any
//     other command compiled into the list ends the node); a colour, normal
//     or material given outside glBegin/glEnd is such a command;
//   - at the end of a node, consecutive primitives merge twice: first as the
//     immediate mode merges them (vbo_merge_draws), then every run of the same
//     mode except GL_LINE_LOOP, GL_TRIANGLE_FAN, GL_QUAD_STRIP and GL_POLYGON
//     becomes one indexed draw (GL_TRIANGLE_STRIPs joined by degenerate
//     triangles, GL_LINE_STRIPs turned into GL_LINES);
//   - a replay draws the buffered immediate-mode vertices first, then each
//     merged draw of the node as a draw of its own;
//   - the first colour or normal of a node given after its first vertex grows
//     the vertex format: the node ends there and a new one starts with the
//     open primitive's unfinished vertices;
//   - GL_COMPILE_AND_EXECUTE executes a node when it ends, by feeding its
//     vertices back through the immediate-mode entry points (Mesa's loopback).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include "pipeline/vertex_batch.h"
#include "state/list_attrib.h"

namespace glfixed {
class Context;
}

namespace glfixed::pipeline {

// One compiled command: a call of an entry point with its arguments copied.
using ListCommand = std::function<void()>;

// A glBegin/glEnd primitive of a node (Mesa's _mesa_prim): its vertices are
// [first, first + count) of the node; begin/end say whether the glBegin and
// the glEnd belong to this node (a format growth can cut a primitive).
struct ListPrimitive {
  GLenum mode;
  uint32_t first = 0, count = 0;
  bool begin = true, end = false;
};

// glMaterial between glBegin and glEnd in a list: applied before vertex `vertex`.
struct ListMaterialCall {
  uint32_t vertex;
  GLenum face, pname;
  GLfloat params[4];
};

struct VertexNode {
  VertexBatch vertices;                      // every vertex as compiled
  std::vector<ListPrimitive> primitives;     // after the first merge: what loopback replays
  std::vector<VertexBatch> draws;            // after the second merge: what a replay draws
  bool hasColor = false, hasNormal = false;  // the node's vertex format
  bool hasEdgeFlag = false;                  // polygon area: a glEdgeFlag inside the node's glBegin/glEnd
  bool loopback = false;                     // replayed through the immediate-mode entry points
  // Vertices carried over from the previous node to continue its open
  // primitive: feeding back skips them (they were fed with that node).
  uint32_t carried = 0;
  // The node ends inside a glBegin/glEnd whose rest is fed back through
  // immediate mode (a glMaterial between glBegin and glEnd follows): its
  // open primitive, vertices [openFirst, end), is not one of its draws but
  // is fed after them, glBegin included.
  bool feedsOpenPrimitive = false;
  GLenum openMode = GL_POINTS;
  uint32_t openFirst = 0;
  std::vector<ListMaterialCall> materials;
  // Other current-attribute calls between glBegin and glEnd (secondary
  // colour, fog coordinate, ...): no stage reads them per vertex yet; run
  // after the node.
  std::vector<ListCommand> attributeCalls;
  // A replay makes the last vertex's colour and normal current, unless the
  // node's last primitive came from an array draw (Mesa's no_current_update:
  // save_DrawArrays begins its primitive with it).
  bool updatesCurrent = true;
};

struct DisplayList {
  std::vector<ListCommand> commands;
};

// The list being compiled, between glNewList and glEndList.
class ListCompiler {
 public:
  ListCompiler(GLuint name, GLenum mode) : name_(name), mode_(mode), list_(std::make_shared<DisplayList>()) {}
  GLuint name() const { return name_; }
  GLenum mode() const { return mode_; }
  bool executes() const { return mode_ == GL_COMPILE_AND_EXECUTE; }
  // Inside a glBegin/glEnd of the list (Mesa's inside_dlist_begin_end).
  bool insideBeginEnd() const { return insideBeginEnd_; }

  // A command: ends the open vertex node, then appends.
  void record(ListCommand command);
  // A GL error of a compiled command (§5.4): raised when the list executes
  // (and at once in GL_COMPILE_AND_EXECUTE, as Mesa's _mesa_compile_error).
  void recordError(Context& ctx, GLenum error);

  // Vertex data inside the list's glBegin/glEnd.
  // `fromArrays`: the glBegin/glEnd of a glDrawArrays or glDrawElements.
  void begin(GLenum mode, bool fromArrays = false);
  void end();
  // glPrimitiveRestartNV between the list's glBegin and glEnd: an end and a
  // begin of the same mode.
  void restartPrimitive() {
    const GLenum mode = beginMode_;
    end();
    begin(mode, lastBeginFromArrays_);
  }
  void vertex(const glm::vec4& position);
  void color(const glm::vec4& c);
  void edgeFlag(bool flag);  // polygon area
  void normal(const glm::vec3& n);
  // Texture coordinates of unit `unit` (0-based): they join the node's vertex
  // format as a colour does.
  void texCoord(int unit, const glm::vec4& c);
  // The fog coordinate: joins the node's vertex format the same way.
  void fogCoord(float f);
  // The secondary colour (the colour sum): joins the format the same way.
  void secondaryColor(const glm::vec4& c);
  void material(GLenum face, GLenum pname, const GLfloat* params, int count);
  void attributeCall(ListCommand call) { node_->attributeCalls.push_back(std::move(call)); }
  // glCallList between glBegin and glEnd in a list: the node ends and the rest
  // of the glBegin/glEnd is compiled as commands (Mesa's dlist_fallback).
  void fallBackToCommands();

  // Mesa skips compiling a glShadeModel that repeats the list's last one
  // (save_ShadeModel); forgotten after a glCallList, whose effect is unknown.
  bool shadeModelRepeats(GLenum mode);
  // The same for glMaterial outside glBegin/glEnd (save_Materialfv): true if
  // every component it sets repeats the value the list last compiled.
  bool materialRepeats(GLenum face, GLenum pname, const GLfloat* params, int count);
  void forgetKnownState() {
    knownShadeModel_ = 0;
    for (auto& m : knownMaterial_) m.count = 0;
  }

  // glEndList: the last node ends; the list is done.
  std::shared_ptr<DisplayList> finish();

 private:
  void endNode();
  void growFormat(bool feedOpenPrimitive = false);

  GLuint name_;
  GLenum mode_;
  std::shared_ptr<DisplayList> list_;
  std::shared_ptr<VertexNode> node_ = std::make_shared<VertexNode>();
  bool insideBeginEnd_ = false;
  bool lastBeginFromArrays_ = false;
  GLenum beginMode_ = GL_POINTS;  // the open glBegin's mode
  glm::vec4 color_{1, 1, 1, 1};
  bool edgeFlag_ = true;  // polygon area
  glm::vec3 normal_{0, 0, 1};
  glm::vec4 texCoord_[kBatchTexCoordUnits];
  float fogCoord_ = 0;
  glm::vec4 secondaryColor_{0, 0, 0, 1};
  // The nodes a format growth ended inside the glBegin/glEnd that goes on in
  // node_: if a node of the chain is fed back on replay, they all must be.
  std::vector<std::shared_ptr<VertexNode>> grownChain_;
  GLenum knownShadeModel_ = 0;
  struct KnownMaterial {
    int count = 0;  // 0: unknown
    GLfloat v[4];
  };
  // [face * 6 + component]: emission, ambient, diffuse, specular, shininess, indexes.
  KnownMaterial knownMaterial_[12];
};

// The lists of a context, shared with the contexts created to share them
// (OSMesaCreateContext's sharelist). As GL requires, an application that uses
// shared lists from several threads at once synchronises itself: a replay
// updates a node's attributes taken from the current values in place.
class DisplayLists {
 public:
  void shareWith(const DisplayLists& other) { lists_ = other.lists_; }
  GLuint genLists(GLsizei range);
  bool isList(GLuint name) const { return lists_->count(name) != 0; }
  void deleteLists(GLuint first, GLsizei range);
  void install(GLuint name, std::shared_ptr<DisplayList> list) { (*lists_)[name] = std::move(list); }
  // glCallList: runs list `name` if it exists and the nesting allows it.
  void call(GLuint name);

  std::unique_ptr<ListCompiler> compiler;  // non-null between glNewList and glEndList
  // > 0 while a list executes: its commands run and are not recorded again.
  int executing = 0;

 private:
  using Names = std::unordered_map<GLuint, std::shared_ptr<DisplayList>>;
  std::shared_ptr<Names> lists_ = std::make_shared<Names>();
  int callDepth_ = 0;
};

// Mesa's two merges of a node's primitives (vbo_save_api.c): merge_prims,
// the immediate mode's merge from the second primitive on; then the index
// buffer's runs of one mode.
std::vector<ListPrimitive> mergeLikeImmediateMode(const std::vector<ListPrimitive>& primitives);
struct IndexedDraw {
  GLenum mode;
  std::vector<uint32_t> indices;  // into the node's vertices
};
std::vector<IndexedDraw> mergeIntoDraws(const std::vector<ListPrimitive>& primitives);

// Draws a node of a list being executed (or feeds it back, see above).
void replayVertexNode(Context& ctx, VertexNode& node);
// Feeds a node's vertices through the immediate-mode entry points.
void loopBackVertexNode(const VertexNode& node);

}  // namespace glfixed::pipeline
