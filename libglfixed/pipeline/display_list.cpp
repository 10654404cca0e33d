#include "pipeline/display_list.h"

#include <algorithm>

#include "pipeline/draw.h"
#include "pipeline/immediate_mode.h"
#include "primitive/merge.h"
#include "state/context.h"
#include "vertex/color_material.h"

namespace glfixed::pipeline {

namespace {

// The fewest vertices of a primitive of `mode` (gallium's u_prim_vertex_count):
// a shorter one is padded with copies of its last vertex.
uint32_t minimumVertices(GLenum mode) {
  switch (mode) {
    case GL_POINTS: return 1;
    case GL_LINES:
    case GL_LINE_STRIP:
    case GL_LINE_LOOP: return 2;
    case GL_QUADS:
    case GL_QUAD_STRIP: return 4;
    default: return 3;
  }
}

// The vertices of an unfinished primitive that continue it after a cut
// (Mesa's vbo_copy_vertices): how many, and whether the first vertex is kept.
uint32_t verticesToCarry(GLenum mode, uint32_t n, bool* keepFirst) {
  *keepFirst = false;
  switch (mode) {
    case GL_POINTS: return 0;
    case GL_LINES: return n % 2;
    case GL_TRIANGLES: return n % 3;
    case GL_QUADS: return n % 4;
    case GL_LINE_STRIP: return n == 0 ? 0 : 1;
    case GL_LINE_LOOP:
    case GL_TRIANGLE_FAN:
    case GL_POLYGON:
      if (n < 2) return n;
      *keepFirst = true;
      return 2;
    default:  // strips keep their winding: an even number of vertices is drawn
      return n <= 1 ? n : 2 + (n & 1);
  }
}

bool joinsRuns(GLenum mode) {
  return mode != GL_LINE_LOOP && mode != GL_TRIANGLE_FAN && mode != GL_QUAD_STRIP && mode != GL_POLYGON;
}

}  // namespace

// Mesa's merge_prims: the immediate mode's merge, within one node. The first
// primitive is not converted (Mesa's loop starts at the second).
std::vector<ListPrimitive> mergeLikeImmediateMode(const std::vector<ListPrimitive>& in) {
  std::vector<ListPrimitive> out;
  for (size_t i = 0; i < in.size(); ++i) {
    ListPrimitive p = in[i];
    if (i == 0) {
      out.push_back(p);
      continue;
    }
    p.mode = primitive::mesaConvertedMode(p.mode, p.count);
    ListPrimitive& prev = out.back();
    if (prev.first + prev.count == p.first &&
        primitive::mesaMergesPrimitives(prev.mode, prev.count, p.mode)) {
      prev.count += p.count;
      prev.end = p.end;
      continue;
    }
    out.push_back(p);
  }
  return out;
}

// Mesa's compile_vertex_list index building: runs of one mode become one draw.
std::vector<IndexedDraw> mergeIntoDraws(const std::vector<ListPrimitive>& prims) {
  std::vector<IndexedDraw> draws;
  for (size_t i = 0; i < prims.size(); ++i) {
    const ListPrimitive& p = prims[i];
    if (p.count == 0) continue;
    const GLenum tested = p.mode == GL_LINE_STRIP ? GL_LINES : p.mode;
    const bool merge = !draws.empty() && draws.back().mode == tested && joinsRuns(tested);
    std::vector<uint32_t> own;
    std::vector<uint32_t>* out = merge ? &draws.back().indices : &own;
    if (merge && tested == GL_TRIANGLE_STRIP) {  // a degenerate triangle joins the strips
      const size_t triangles = out->size() - 2;
      out->push_back(out->back());
      out->push_back(p.first);
      if (triangles % 2) out->push_back(p.first);  // keeps the winding
    }
    GLenum mode = p.mode;
    const bool nextIsLine =
        i + 1 < prims.size() && (prims[i + 1].mode == GL_LINE_STRIP || prims[i + 1].mode == GL_LINES);
    if (p.mode == GL_LINE_STRIP && (merge || nextIsLine)) {
      mode = GL_LINES;
      for (uint32_t j = 0; j < p.count; ++j) {
        out->push_back(p.first + j);
        if (j && j != p.count - 1) out->push_back(p.first + j);
      }
    } else {
      for (uint32_t j = 0; j < p.count; ++j) out->push_back(p.first + j);
    }
    for (uint32_t j = p.count; j < minimumVertices(mode); ++j) out->push_back(p.first + p.count - 1);
    if (!merge) draws.push_back({mode, std::move(own)});
    draws.back().mode = mode;
  }
  return draws;
}

// ---- ListCompiler -----------------------------------------------------------

void ListCompiler::record(ListCommand command) {
  endNode();
  list_->commands.push_back(std::move(command));
}

void ListCompiler::recordError(Context& ctx, GLenum error) {
  record([error] {
    if (Context* c = currentContext()) c->recordError(error);
  });
  if (executes()) ctx.recordError(error);
}

void ListCompiler::begin(GLenum mode, bool fromArrays) {
  lastBeginFromArrays_ = fromArrays;
  beginMode_ = mode;
  VertexNode& n = *node_;
  ListPrimitive p;
  p.mode = mode;
  p.first = static_cast<uint32_t>(n.vertices.size());
  n.primitives.push_back(p);
  insideBeginEnd_ = true;
}

void ListCompiler::end() {
  ListPrimitive& p = node_->primitives.back();
  p.count = static_cast<uint32_t>(node_->vertices.size()) - p.first;
  p.end = true;
  insideBeginEnd_ = false;
}

void ListCompiler::vertex(const glm::vec4& position) {
  VertexBatch& v = node_->vertices;
  v.position.push_back(position);
  v.normal.push_back(normal_);
  v.color.push_back(color_);
  v.materialIndex.push_back(0);
  v.edgeFlag.push_back(edgeFlag_);  // polygon area
  for (uint32_t m = v.texCoordUnits; m != 0; m &= m - 1) v.texCoord[__builtin_ctz(m)].push_back(texCoord_[__builtin_ctz(m)]);
  if (v.hasFogCoord) v.fogCoord.push_back(fogCoord_);
  if (v.hasSecondaryColor) v.secondaryColor.push_back(secondaryColor_);
}

// Polygon area: the edge flag joins the node's vertices without growing its
// format (not measured against Mesa's save module, which grows it).
void ListCompiler::edgeFlag(bool flag) {
  node_->hasEdgeFlag = true;
  edgeFlag_ = flag;
}

void ListCompiler::color(const glm::vec4& c) {
  if (!node_->hasColor) growFormat();
  node_->hasColor = true;
  color_ = c;
}

void ListCompiler::normal(const glm::vec3& n) {
  if (!node_->hasNormal) growFormat();
  node_->hasNormal = true;
  normal_ = n;
}

void ListCompiler::texCoord(int unit, const glm::vec4& c) {
  const uint32_t bit = 1u << unit, before = node_->vertices.texCoordUnits;
  if (!(before & bit)) {
    growFormat();
    node_->vertices.setTexCoordUnits(node_->vertices.texCoordUnits | before | bit);
  }
  texCoord_[unit] = c;
}

void ListCompiler::fogCoord(float f) {
  if (!node_->vertices.hasFogCoord) {
    growFormat();
    node_->vertices.setHasFogCoord(true);
  }
  fogCoord_ = f;
}

void ListCompiler::secondaryColor(const glm::vec4& c) {
  if (!node_->vertices.hasSecondaryColor) {
    growFormat();
    node_->vertices.setHasSecondaryColor(true);
  }
  secondaryColor_ = c;
}

void ListCompiler::material(GLenum face, GLenum pname, const GLfloat* params, int count) {
  // Mesa keeps these materials as vertex attributes: the first grows the
  // format. This node is fed back through immediate mode, and so is the rest
  // of its glBegin/glEnd in the nodes before it (growFormat).
  if (node_->materials.empty()) {
    const bool grownBefore = !grownChain_.empty();  // a colour or normal cut this glBegin/glEnd already
    growFormat(!grownBefore);
    if (grownBefore)
      for (auto& n : grownChain_) n->loopback = true;
  }
  ListMaterialCall m{static_cast<uint32_t>(node_->vertices.size()), face, pname, {0, 0, 0, 0}};
  std::copy(params, params + count, m.params);
  node_->materials.push_back(m);
  node_->loopback = true;  // per-vertex materials: replayed as immediate-mode calls
}

// An attribute enters the vertex format of a node that already has vertices
// (Mesa's upgrade_vertex): the node ends, and the unfinished vertices of the
// open primitive start the next node, which continues the primitive.
void ListCompiler::growFormat(bool feedOpenPrimitive) {
  VertexNode& old = *node_;
  if (old.vertices.size() == 0) return;
  auto next = std::make_shared<VertexNode>();
  next->hasColor = old.hasColor;
  next->hasNormal = old.hasNormal;
  next->hasEdgeFlag = old.hasEdgeFlag;  // polygon area
  if (insideBeginEnd_) {
    ListPrimitive& open = old.primitives.back();
    open.count = static_cast<uint32_t>(old.vertices.size()) - open.first;
    bool keepFirst;
    const uint32_t carry = std::min(verticesToCarry(open.mode, open.count, &keepFirst), open.count);
    const uint32_t last = open.first + open.count;
    if (keepFirst) next->vertices.appendVertices(old.vertices, open.first, open.first + 1);
    const uint32_t tail = keepFirst ? carry - 1 : carry;
    next->vertices.appendVertices(old.vertices, last - tail, last);
    next->carried = carry;
    ListPrimitive cont;
    cont.mode = open.mode;
    cont.begin = false;
    next->primitives.push_back(cont);
  }
  // The fog coordinate stays in the format of the nodes that follow.
  if (old.vertices.hasFogCoord && !next->vertices.hasFogCoord) next->vertices.setHasFogCoord(true);
  if (old.vertices.hasSecondaryColor && !next->vertices.hasSecondaryColor) next->vertices.setHasSecondaryColor(true);
  if (insideBeginEnd_ && feedOpenPrimitive) {
    const ListPrimitive open = old.primitives.back();
    old.primitives.pop_back();
    old.feedsOpenPrimitive = true;
    old.openMode = open.mode;
    old.openFirst = open.first;
  }
  // Compile the old node with the open primitive left unfinished.
  const bool inside = insideBeginEnd_;
  std::shared_ptr<VertexNode> ended = node_;
  std::vector<std::shared_ptr<VertexNode>> chain = std::move(grownChain_);
  insideBeginEnd_ = false;
  endNode();
  insideBeginEnd_ = inside;
  node_ = next;
  if (inside) {
    grownChain_ = std::move(chain);
    grownChain_.push_back(ended);
  }
}

void ListCompiler::fallBackToCommands() {
  if (insideBeginEnd_) {
    ListPrimitive& open = node_->primitives.back();
    open.count = static_cast<uint32_t>(node_->vertices.size()) - open.first;
    node_->loopback = true;  // the primitive continues outside the node
  }
  insideBeginEnd_ = false;
  endNode();
}

bool ListCompiler::shadeModelRepeats(GLenum mode) {
  if (knownShadeModel_ == mode) return true;
  knownShadeModel_ = mode;
  return false;
}

bool ListCompiler::materialRepeats(GLenum face, GLenum pname, const GLfloat* params, int count) {
  uint32_t components = 0;  // bits of the component order above
  switch (pname) {
    case GL_EMISSION: components = 1; break;
    case GL_AMBIENT: components = 2; break;
    case GL_DIFFUSE: components = 4; break;
    case GL_SPECULAR: components = 8; break;
    case GL_SHININESS: components = 16; break;
    case GL_COLOR_INDEXES: components = 32; break;
    case GL_AMBIENT_AND_DIFFUSE: components = 6; break;
    default: return false;
  }
  bool repeats = true;
  for (int f = 0; f < 2; ++f) {
    if ((f == 0 && face == GL_BACK) || (f == 1 && face == GL_FRONT)) continue;
    for (int c = 0; c < 6; ++c) {
      if (!(components & (1u << c))) continue;
      KnownMaterial& k = knownMaterial_[f * 6 + c];
      if (k.count == count && std::equal(params, params + count, k.v)) continue;
      repeats = false;
      k.count = count;
      std::copy(params, params + count, k.v);
    }
  }
  return repeats;
}

void ListCompiler::endNode() {
  if (insideBeginEnd_) return;  // the node continues (glMaterial inside glBegin/glEnd)
  std::shared_ptr<VertexNode> node = node_;
  grownChain_.clear();
  if (node->primitives.empty() && node->attributeCalls.empty() && !node->feedsOpenPrimitive) return;
  node_ = std::make_shared<VertexNode>();
  node->updatesCurrent = !lastBeginFromArrays_;
  node->primitives = mergeLikeImmediateMode(node->primitives);
  for (IndexedDraw& d : mergeIntoDraws(node->primitives)) {
    VertexBatch b;
    b.mode = d.mode;
    for (uint32_t i : d.indices) b.appendVertices(node->vertices, i, i + 1);
    for (uint32_t& m : b.materialIndex) m = 0;
    b.materials.resize(1);
    node->draws.push_back(std::move(b));
  }
  list_->commands.push_back([node] {
    if (Context* c = currentContext()) replayVertexNode(*c, *node);
  });
  if (executes()) {
    Context* ctx = currentContext();
    if (!ctx) return;
    ++ctx->displayLists.executing;
    loopBackVertexNode(*node);
    for (const ListCommand& call : node->attributeCalls) call();
    --ctx->displayLists.executing;
  }
}

std::shared_ptr<DisplayList> ListCompiler::finish() {
  if (insideBeginEnd_) fallBackToCommands();  // a list may end inside glBegin/glEnd
  endNode();
  return list_;
}

// ---- DisplayLists -------------------------------------------------------------

GLuint DisplayLists::genLists(GLsizei range) {
  // GL 2.1 §5.4: 0 when no run of `range` unused names is available; here
  // also for more than a million at once, whose empty lists alone would
  // take gigabytes.
  constexpr GLsizei kMaxRange = 1 << 20;
  if (range <= 0 || range > kMaxRange) return 0;
  // The first run of `range` unused names above every used one, or any gap.
  GLuint first = 1;
  for (;;) {
    GLuint n = 0;
    while (n < static_cast<GLuint>(range) && lists_->count(first + n) == 0) ++n;
    if (n == static_cast<GLuint>(range)) break;
    first += n + 1;
    if (first == 0 || first > 0xFFFFFFFFu - static_cast<GLuint>(range)) return 0;
  }
  for (GLuint i = 0; i < static_cast<GLuint>(range); ++i)
    (*lists_)[first + i] = std::make_shared<DisplayList>();
  return first;
}

void DisplayLists::deleteLists(GLuint first, GLsizei range) {
  if (range <= 0) return;
  const uint64_t last = static_cast<uint64_t>(first) + static_cast<uint64_t>(range);  // one past
  if (static_cast<uint64_t>(range) > lists_->size()) {  // a huge range: look at the lists instead
    for (auto it = lists_->begin(); it != lists_->end();)
      it = (it->first >= first && it->first < last) ? lists_->erase(it) : std::next(it);
    return;
  }
  for (uint64_t name = first; name < last && name <= 0xFFFFFFFFu; ++name)
    lists_->erase(static_cast<GLuint>(name));
}

void DisplayLists::call(GLuint name) {
  if (callDepth_ >= kMaxListNesting) return;  // deeper calls are ignored (§5.4)
  auto it = lists_->find(name);
  if (it == lists_->end()) return;                 // a list that does not exist: nothing happens
  std::shared_ptr<DisplayList> list = it->second;  // kept alive while it runs
  ++callDepth_;
  ++executing;
  for (const ListCommand& command : list->commands) command();
  --executing;
  --callDepth_;
}

// ---- Replay -----------------------------------------------------------------

namespace {
void feedOpenPrimitive(const VertexNode& node) {
  const VertexBatch& v = node.vertices;
  glBegin(node.openMode);
  for (uint32_t i = node.openFirst; i < v.size(); ++i) {
    if (node.hasColor) glColor4fv(&v.color[i][0]);
    if (node.hasNormal) glNormal3fv(&v.normal[i][0]);
    if (node.hasEdgeFlag) glEdgeFlag(v.edgeFlag[i]);
    glVertex4fv(&v.position[i][0]);
  }
}
}  // namespace

void loopBackVertexNode(const VertexNode& node) {
  const VertexBatch& v = node.vertices;
  size_t material = 0;
  auto materialsUpTo = [&](uint32_t vertex) {
    for (; material < node.materials.size() && node.materials[material].vertex <= vertex; ++material) {
      const ListMaterialCall& m = node.materials[material];
      glMaterialfv(m.face, m.pname, m.params);
    }
  };
  for (const ListPrimitive& p : node.primitives) {
    if (p.begin) glBegin(p.mode);
    const uint32_t skip = p.begin ? 0 : node.carried;
    for (uint32_t i = p.first + skip; i < p.first + p.count; ++i) {
      materialsUpTo(i);
      if (node.hasColor) glColor4fv(&v.color[i][0]);
      if (node.hasNormal) glNormal3fv(&v.normal[i][0]);
      if (node.hasEdgeFlag) glEdgeFlag(v.edgeFlag[i]);
      for (uint32_t m = v.texCoordUnits; m != 0; m &= m - 1) {
        const int u = __builtin_ctz(m);
        glMultiTexCoord4fv(GL_TEXTURE0 + u, &v.texCoord[u][i][0]);
      }
      if (v.hasFogCoord) glFogCoordf(v.fogCoord[i]);
      if (v.hasSecondaryColor) glSecondaryColor3fv(&v.secondaryColor[i][0]);
      glVertex4fv(&v.position[i][0]);
    }
    materialsUpTo(p.first + p.count);
    if (p.end) glEnd();
  }
  if (node.feedsOpenPrimitive) feedOpenPrimitive(node);
}

void replayVertexNode(Context& ctx, VertexNode& node) {
  if (ctx.insideBeginEnd || node.loopback) {
    // Called between glBegin and glEnd: only a node that continues the open
    // primitive can run (Mesa: "draw operation inside glBegin/End").
    if (ctx.insideBeginEnd && !node.primitives.empty() && node.primitives.front().begin) {
      ctx.recordError(GL_INVALID_OPERATION);
      return;
    }
    loopBackVertexNode(node);
  } else if (!node.draws.empty()) {
    flushVertices(ctx);  // Mesa's FLUSH_FOR_DRAW: the immediate-mode vertices first
    for (VertexBatch& b : node.draws) {
      // Attributes outside the node's format take the current values.
      if (!node.hasColor && b.size() && b.color[0] != ctx.current.color)
        std::fill(b.color.begin(), b.color.end(), ctx.current.color);
      if (!node.hasNormal && b.size() && b.normal[0] != ctx.current.normal)
        std::fill(b.normal.begin(), b.normal.end(), ctx.current.normal);
      b.materials[0] = ctx.lighting.material;
      if (!node.hasEdgeFlag) std::fill(b.edgeFlag.begin(), b.edgeFlag.end(), ctx.current.edgeFlag);
      drawBatch(ctx, b, primitive::PrimitiveState::Submission::kDisplayList, node.hasColor, false,
                node.vertices.hasSecondaryColor);
    }
    ctx.vbo = Context::VboFormat();
    // The last vertex's attributes become current (Mesa's current_data).
    const VertexBatch& v = node.vertices;
    if (v.size() > 0 && node.updatesCurrent) {
      for (uint32_t m = v.texCoordUnits; m != 0; m &= m - 1)
        ctx.current.texCoord[__builtin_ctz(m)] = v.texCoord[__builtin_ctz(m)].back();
      if (v.hasFogCoord) ctx.current.fogCoord = v.fogCoord.back();
      if (v.hasSecondaryColor) ctx.current.secondaryColor = v.secondaryColor.back();
      if (node.hasNormal) ctx.current.normal = v.normal.back();
      if (node.hasEdgeFlag) ctx.current.edgeFlag = v.edgeFlag.back() != 0;
      if (node.hasColor) {
        ctx.current.color = v.color.back();
        if (ctx.lighting.colorMaterial) trackColorMaterial(ctx);
      }
    }
  }
  for (const ListCommand& call : node.attributeCalls) call();
  if (node.feedsOpenPrimitive && !node.loopback && !ctx.insideBeginEnd) feedOpenPrimitive(node);
}

}  // namespace glfixed::pipeline
