// Parent table, cycle detection and world transforms, all iterative. With at most one parent per
// node the graph is a forest plus cycles; a node that no walk from a parentless node reaches sits
// on a cycle or below one.
#include "read/node_hierarchy.h"

#include <cfloat>
#include <cmath>
#include <deque>

namespace lintel::scene_read {
namespace {

Status build_parents(const LoadContext& ctx, const std::vector<NodeRecord>& nodes, std::vector<int>& parent) {
  parent.assign(nodes.size(), -1);
  for (size_t p = 0; p < nodes.size(); ++p) {
    for (uint32_t c : nodes[p].children) {
      if (c == p) return ctx.fail(nodes[p].element, "node hierarchy cycle: the node is its own child");
      if (parent[c] == int(p)) return ctx.fail(nodes[p].element, "lists child " + std::to_string(c) + " twice");
      if (parent[c] != -1)
        return ctx.fail(nodes[c].element,
                        "has two parents (node " + std::to_string(parent[c]) + " and node " + std::to_string(p) + ")");
      parent[c] = int(p);
    }
  }
  return {};
}

Status find_cycles(const LoadContext& ctx, const std::vector<NodeRecord>& nodes, const std::vector<int>& parent) {
  std::vector<uint8_t> reached(nodes.size(), 0);
  std::vector<uint32_t> stack;
  for (size_t i = 0; i < nodes.size(); ++i)
    if (parent[i] == -1) stack.push_back(uint32_t(i));
  while (!stack.empty()) {
    const uint32_t n = stack.back();
    stack.pop_back();
    reached[n] = 1;
    for (uint32_t c : nodes[n].children) stack.push_back(c);
  }
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (reached[i]) continue;
    // Walk up until a node repeats: that node lies on the cycle, name it.
    std::vector<uint8_t> seen(nodes.size(), 0);
    size_t n = i;
    while (!seen[n]) {
      seen[n] = 1;
      n = size_t(parent[n]);  // never -1 here: that walk would have reached node i
    }
    return ctx.fail(nodes[n].element, "node hierarchy cycle through this node");
  }
  return {};
}

bool finite_as_float(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!(std::fabs(m[c][r]) <= double(FLT_MAX))) return false;
  return true;
}

}  // namespace

Status build_scene_graph(const LoadContext& ctx, const std::vector<NodeRecord>& nodes, const SceneChoice& choice,
                         SceneGraph& out) {
  out = {};
  if (Status s = build_parents(ctx, nodes, out.parent); !s) return s;
  if (Status s = find_cycles(ctx, nodes, out.parent); !s) return s;

  std::vector<uint32_t> roots;
  if (choice.scene) {
    std::vector<uint8_t> listed(nodes.size(), 0);
    for (uint32_t r : choice.roots) {
      if (out.parent[r] != -1)
        return ctx.fail(choice.element,
                        "root " + nodes[r].element + " is a child of node " + std::to_string(out.parent[r]));
      if (listed[r]) return ctx.fail(choice.element, "lists root " + nodes[r].element + " twice");
      listed[r] = 1;
      roots.push_back(r);
    }
  } else {
    for (size_t i = 0; i < nodes.size(); ++i)
      if (out.parent[i] == -1) roots.push_back(uint32_t(i));
  }

  out.in_scene.assign(nodes.size(), 0);
  out.world.assign(nodes.size(), glm::dmat4(1.0));
  out.cell_ancestor.assign(nodes.size(), -1);
  std::deque<uint32_t> queue(roots.begin(), roots.end());
  for (uint32_t r : roots) out.world[r] = nodes[r].local;
  while (!queue.empty()) {
    const uint32_t n = queue.front();
    queue.pop_front();
    out.in_scene[n] = 1;
    if (!finite_as_float(out.world[n])) return ctx.fail(nodes[n].element, "world transform is not finite (overflow)");
    const int cell_here = nodes[n].tag.kind == NodeTag::Kind::Cell ? int(n) : out.cell_ancestor[n];
    for (uint32_t c : nodes[n].children) {
      out.world[c] = out.world[n] * nodes[c].local;
      out.cell_ancestor[c] = cell_here;
      queue.push_back(c);
    }
  }
  return {};
}

}  // namespace lintel::scene_read
