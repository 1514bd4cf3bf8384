#include "ossa/level/box_tree.h"

#include <algorithm>
#include <climits>
#include <limits>

#include "ossa/assert.h"

namespace ossa {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
// Median splits give depth <= log2(n) + 1 <= 32 for any int count; a depth-first traversal
// never holds more than depth + 1 nodes.
constexpr int kStackSize = 64;

// Items in a leaf: highest top first, ties by lower collider index, so the first ground
// candidate met in a leaf is the leaf's answer.
template <class ItemT>
bool higher_top(const ItemT& a, const ItemT& b) {
  if (a.box.max_ws.y != b.box.max_ws.y) return a.box.max_ws.y > b.box.max_ws.y;
  return a.index < b.index;
}

// Conservative (closed) version of sweep_against for node bounds: the earliest t at which
// `moving` may touch `bounds`, or +inf if it cannot within [0, 1]. Float division and
// subtraction are monotonic, so a node's entry time never exceeds that of a box inside it.
float sweep_entry(const Box& bounds, const Box& moving, glm::vec2 delta) {
  float t0 = -kInf, t1 = kInf;
  for (int a = 0; a < 2; ++a) {
    const float emin = bounds.min_ws[a] - moving.max_ws[a];
    const float emax = bounds.max_ws[a] - moving.min_ws[a];
    const float d = delta[a];
    if (d == 0.0f) {
      if (!(emin <= 0.0f && 0.0f <= emax)) return kInf;
      continue;
    }
    t0 = std::max(t0, (d > 0.0f ? emin : emax) / d);
    t1 = std::min(t1, (d > 0.0f ? emax : emin) / d);
  }
  if (!(t0 <= t1) || !(t0 <= 1.0f) || !(t1 >= 0.0f)) return kInf;
  return std::max(t0, 0.0f);
}

}  // namespace

void BoxTree::build(const std::vector<Box>& boxes) {
  OSSA_ASSERT(boxes.size() < static_cast<size_t>(INT_MAX / 2), "too many boxes");
  const int n = static_cast<int>(boxes.size());
  items_.resize(n);
  for (int i = 0; i < n; ++i) items_[i] = {boxes[i], i};
  nodes_.clear();
  parent_.clear();
  nodes_.reserve(n > 0 ? 2 * (n / kLeafSize + 1) : 0);
  parent_.reserve(nodes_.capacity());
  item_of_.assign(n, 0);
  leaf_of_.assign(n, 0);
  if (n > 0) build_node(0, n, -1);
}

int BoxTree::build_node(int begin, int end, int parent) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  parent_.push_back(parent);
  const int count = end - begin;
  const bool leaf = count <= kLeafSize || (begin == 0 && end == size() && count <= kLinearThreshold);
  if (leaf) {
    nodes_[id].first = begin;
    nodes_[id].count = count;
    sort_leaf(id);
    nodes_[id].bounds = leaf_bounds(nodes_[id]);
    return id;
  }
  // Split at the median centre along the longer axis of the centres' extent.
  Box c{items_[begin].box.center(), items_[begin].box.center()};
  for (int i = begin + 1; i < end; ++i) {
    const glm::vec2 p = items_[i].box.center();
    c = c.united({p, p});
  }
  const int axis = c.width() >= c.height() ? 0 : 1;
  const int mid = begin + count / 2;
  std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                   [axis](const Item& a, const Item& b) {
                     return a.box.min_ws[axis] + a.box.max_ws[axis] <
                            b.box.min_ws[axis] + b.box.max_ws[axis];
                   });
  const int left = build_node(begin, mid, id);
  const int right = build_node(mid, end, id);
  OSSA_ASSERT(left == id + 1, "left child follows its parent");
  nodes_[id].first = right;
  nodes_[id].count = 0;
  nodes_[id].bounds = nodes_[left].bounds.united(nodes_[right].bounds);
  return id;
}

void BoxTree::sort_leaf(int node) {
  const Node& n = nodes_[node];
  std::sort(items_.begin() + n.first, items_.begin() + n.first + n.count, higher_top<Item>);
  for (int i = n.first; i < n.first + n.count; ++i) {
    item_of_[items_[i].index] = i;
    leaf_of_[i] = node;
  }
}

Box BoxTree::leaf_bounds(const Node& n) const {
  Box b = items_[n.first].box;
  for (int i = n.first + 1; i < n.first + n.count; ++i) b = b.united(items_[i].box);
  return b;
}

void BoxTree::update(int index, const Box& box) {
  OSSA_ASSERT(index >= 0 && index < size(), "box index out of range");
  const int pos = item_of_[index];
  items_[pos].box = box;
  int node = leaf_of_[pos];
  sort_leaf(node);
  nodes_[node].bounds = leaf_bounds(nodes_[node]);
  // Refit the ancestors: each inner node is the union of its two children.
  for (node = parent_[node]; node >= 0; node = parent_[node]) {
    nodes_[node].bounds = nodes_[node + 1].bounds.united(nodes_[nodes_[node].first].bounds);
  }
}

template <class Skip, class Leaf, class LeftFirst>
void BoxTree::walk(Skip&& skip, Leaf&& leaf, LeftFirst&& left_first) const {
  if (nodes_.empty()) return;
  int stack[kStackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int id = stack[--top];
    const Node& n = nodes_[id];
    if (skip(n)) continue;
    if (n.count > 0) {
      if (!leaf(n)) return;
      continue;
    }
    const int l = id + 1, r = n.first;
    if (left_first(l, r)) {
      stack[top++] = r;
      stack[top++] = l;
    } else {
      stack[top++] = l;
      stack[top++] = r;
    }
  }
}

std::optional<GroundHit> BoxTree::ground(float x_min, float x_max, float lo, float hi) const {
  float best_h = -kInf;
  int best_i = INT_MAX;
  walk(
      [&](const Node& n) {
        const Box& b = n.bounds;
        // No box below can be higher than min(bounds top, hi): skip if that cannot win.
        return b.min_ws.x > x_max || b.max_ws.x < x_min || b.max_ws.y < lo || b.min_ws.y > hi || std::min(b.max_ws.y, hi) < best_h;
      },
      [&](const Node& n) {
        for (const Item* it = &items_[n.first], *e = it + n.count; it != e; ++it) {
          const float h = it->box.max_ws.y;
          if (h > hi) continue;
          if (h < lo || h < best_h) break;  // sorted by top: nothing further can win
          if (it->box.min_ws.x <= x_max && it->box.max_ws.x >= x_min) {
            if (h > best_h || it->index < best_i) {
              best_h = h;
              best_i = it->index;
            }
            break;
          }
        }
        return true;
      },
      // The child that may hold the higher top first, so pruning starts early.
      [&](int l, int r) { return nodes_[l].bounds.max_ws.y > nodes_[r].bounds.max_ws.y; });
  if (best_i == INT_MAX) return std::nullopt;
  return GroundHit{best_h, best_i};
}

bool BoxTree::any_overlap(const Box& box) const {
  bool found = false;
  walk([&](const Node& n) { return !n.bounds.overlaps(box); },
       [&](const Node& n) {
         for (int i = n.first; i < n.first + n.count && !found; ++i) found = items_[i].box.overlaps(box);
         return !found;
       },
       [](int, int) { return true; });
  return found;
}

int BoxTree::lowest_overlap(const Box& box) const {
  int best = INT_MAX;
  walk([&](const Node& n) { return !n.bounds.overlaps(box); },
       [&](const Node& n) {
         for (int i = n.first; i < n.first + n.count; ++i) {
           if (items_[i].index < best && items_[i].box.overlaps(box)) best = items_[i].index;
         }
         return true;
       },
       [](int, int) { return true; });
  return best == INT_MAX ? -1 : best;
}

void BoxTree::overlapping(const Box& box, std::vector<int>& out) const {
  const size_t start = out.size();
  walk([&](const Node& n) { return !n.bounds.overlaps(box); },
       [&](const Node& n) {
         for (int i = n.first; i < n.first + n.count; ++i) {
           if (items_[i].box.overlaps(box)) out.push_back(items_[i].index);
         }
         return true;
       },
       [](int, int) { return true; });
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(start), out.end());
}

std::optional<SweepHit> BoxTree::sweep(const Box& moving, glm::vec2 delta) const {
  std::optional<SweepHit> best;
  walk(
      [&](const Node& n) {
        const float entry = sweep_entry(n.bounds, moving, delta);
        return entry == kInf || (best && entry > best->t);
      },
      [&](const Node& n) {
        for (int i = n.first; i < n.first + n.count; ++i) {
          std::optional<SweepHit> hit = sweep_against(moving, delta, items_[i].box);
          if (!hit) continue;
          if (!best || hit->t < best->t || (hit->t == best->t && items_[i].index < best->index)) {
            best = hit;
            best->index = items_[i].index;
          }
        }
        return true;
      },
      // The nearer child first.
      [&](int l, int r) { return sweep_entry(nodes_[l].bounds, moving, delta) <= sweep_entry(nodes_[r].bounds, moving, delta); });
  return best;
}

}  // namespace ossa
