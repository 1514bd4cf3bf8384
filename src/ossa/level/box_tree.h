#pragma once
// BoxTree — the spatial index behind Level's queries: a static bounding-volume hierarchy over
// the colliders, built top-down by median splits (O(n log n), depth <= log2(n) + 1).
//
// Leaves hold up to kLeafSize boxes stored inside the tree (contiguous, so a leaf scan is one
// cache-friendly loop), sorted by top height, highest first, so the ground query can stop at
// the first match in a leaf. A tree of at most kLinearThreshold boxes is one leaf: small
// levels are answered by a plain scan that is as fast as a linear search.
//
// Every query returns exactly what a linear scan over all boxes would return, ties broken by
// the lowest collider index (tests/level/level_query_test.cpp checks this at 100 000 boxes).
// Level owns a BoxTree; use Level rather than this class directly.

#include <optional>
#include <vector>

#include "ossa/level/box.h"

namespace ossa {

class BoxTree {
 public:
  static constexpr int kLeafSize = 4;
  static constexpr int kLinearThreshold = 32;

  // Rebuilds the tree over `boxes` (index i of the results refers to boxes[i]).
  void build(const std::vector<Box>& boxes);
  // Replaces box `index` and refits the bounds on its path to the root: O(leaf + depth).
  // The tree stays correct; its quality drops if boxes move far, so rebuild now and then.
  void update(int index, const Box& box);
  int size() const { return static_cast<int>(items_.size()); }
  // The smallest box holding every box (the root's bounds: exact, as update() refits from the
  // children), or nullopt for an empty tree. O(1).
  std::optional<Box> bounds() const {
    if (nodes_.empty()) return std::nullopt;
    return nodes_.front().bounds;
  }

  // Highest box top in [lo, hi] among boxes touching [x_min, x_max] (is_ground_candidate).
  std::optional<GroundHit> ground(float x_min, float x_max, float lo, float hi) const;
  // Any box whose interior overlaps `box`.
  bool any_overlap(const Box& box) const;
  // The lowest index of a box overlapping `box`, or -1.
  int lowest_overlap(const Box& box) const;
  // Appends the indices of all boxes overlapping `box`, in increasing order.
  void overlapping(const Box& box, std::vector<int>& out) const;
  // The first box hit by `moving` swept along `delta` (sweep_against), smallest t first.
  std::optional<SweepHit> sweep(const Box& moving, glm::vec2 delta) const;

 private:
  struct Item {
    Box box;
    int index;
  };
  // count > 0: leaf over items_[first, first + count); count == 0: inner node whose left
  // child is the next node and whose right child is nodes_[first].
  struct Node {
    Box bounds;
    int first = 0;
    int count = 0;
  };

  // The one traversal of the tree, depth first from the root: a node `skip(node)` says is of
  // no use is left with all below it; `leaf(node)` visits a leaf's items and returns false to
  // end the walk; an inner node's left child (node index + 1) is visited before its right one
  // (nodes_[first]) when `left_first(left, right)` (the node indices) says so.
  template <class Skip, class Leaf, class LeftFirst>
  void walk(Skip&& skip, Leaf&& leaf, LeftFirst&& left_first) const;

  int build_node(int begin, int end, int parent);
  void sort_leaf(int node);
  Box leaf_bounds(const Node& n) const;

  std::vector<Node> nodes_;
  std::vector<int> parent_;       // per node, -1 for the root
  std::vector<Item> items_;       // in leaf order
  std::vector<int> item_of_;      // collider index -> position in items_
  std::vector<int> leaf_of_;      // position in items_ -> leaf node
};

}  // namespace ossa
