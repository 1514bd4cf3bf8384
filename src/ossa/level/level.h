#pragma once
// Level — the ground creatures walk on (DESIGN.md §6, [T 4.3]): a list of axis-aligned boxes
// (colliders), a spawn point and an optional background.
//
// Space: world, metres, +x right, +y up. All queries go through a spatial index (BoxTree, a
// static bounding-volume hierarchy) and answer exactly what a linear scan over all boxes
// would, ties broken by the lowest collider index. Small levels (<= 32 boxes) are a single
// index leaf, so they cost no more than a linear scan; a level may hold 1 000 000 boxes.
//
// Editing (for the level editor): add_box / remove_box / set_box keep the index in step.
// add and remove rebuild it (O(n log n), ~10 ms at 100 000 boxes); set_box refits it in
// O(log n) so dragging a box is cheap, and rebuilds after many refits to keep queries fast.
//
// Example:
//   Level level;
//   level.add_box(Box::from_corner(0.0f, -1.0f, 60.0f, 1.0f));   // ground, top at y = 0
//   auto ground = level.ground_height_below(x - 0.05f, x + 0.05f, foot_y + 0.5f, 1.5f);
//   if (ground) foot_y = ground->height_ws;

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ossa/level/box.h"
#include "ossa/level/box_tree.h"
#include "ossa/level/level_art.h"

namespace ossa {

// What is drawn behind the level. Optional; the renderer clears to `colour` and, if `image`
// is set, draws it scrolled by `parallax`.
struct Background {
  std::string image;                          // image path relative to assets/, or empty
  float parallax = 0.5f;                      // scroll factor in [0, 1]: 0 = fixed to the
                                              // screen (infinitely far), 1 = moves with the level
  glm::vec3 colour{0.55f, 0.70f, 0.85f};      // linear RGB in [0, 1], the clear colour

  friend bool operator==(const Background& a, const Background& b) {
    return a.image == b.image && a.parallax == b.parallax && a.colour == b.colour;
  }
};

// How an ossa level's boxes look (DESIGN.md §6: "ossa's own levels may name a tileset for box
// tops, sides and fill"): tiles of one tileset image laid on a world grid of tile_m metres,
// clipped to each box. The fill covers the box; a side column runs down each side no other box
// covers, the top row along the top no other box covers (its corners where the top meets an
// exposed side). Tiles are numbered in row order from the image's top-left, 0-based.
struct LevelLook {
  std::string tileset;      // image path relative to the level's folder, else assets/
  int tile_px = 32;         // a tile's width and height in the image, pixels, > 0
  float tile_m = 0.5f;      // a tile's width and height in the world, metres, > 0
  int top = 0;              // the top row (grass), >= 0
  int top_left = -1;        // the top row's corners; -1: `top`
  int top_right = -1;
  int left = -1;            // the side columns; -1: no side column (the fill reaches the edge)
  int right = -1;
  int fill = 0;             // everything else, >= 0

  friend bool operator==(const LevelLook&, const LevelLook&) = default;
};

class Level {
 public:
  // Free to edit; no invariant ties them to the colliders.
  std::string name;                     // shown in the editor; may be empty
  glm::vec2 spawn_ws{0.0f};             // where the player's creature starts (on the ground)
  std::optional<Background> background;
  // An ossa level's box tiles (saved with the level), or none: plain earth-coloured boxes.
  std::optional<LevelLook> look;
  // A Tiled map's or an LDtk level's art (level_art.h), shared by copies of the level; null for
  // ossa levels. Not saved by save_level (an ossa level has no tile layers) and not compared
  // by operator== (collision and spawn are what a level is; the art is how it looks).
  std::shared_ptr<const LevelArt> art;
  // A creature that falls to this height (world y, metres: where its feet would stand under
  // its root) has left the level and starts again at the spawn; a pit's floor may be it.
  // Unset: kill_y()'s default.
  std::optional<float> kill_height_ws;

  Level() = default;
  // Every box must be valid (Box::is_valid()).
  explicit Level(std::vector<Box> colliders, glm::vec2 spawn_ws = glm::vec2(0.0f), std::string name = {});

  // ---- Colliders and editing ------------------------------------------------------------
  const std::vector<Box>& colliders() const { return colliders_; }
  int size() const { return static_cast<int>(colliders_.size()); }
  bool empty() const { return colliders_.empty(); }
  const Box& box(int index) const;
  // Smallest box holding every collider and the spawn point. O(1) (the index's root).
  Box bounds() const;

  // Appends a valid box and returns its index (size() - 1).
  int add_box(const Box& box);
  // Removes box `index`; later boxes shift down by one index.
  void remove_box(int index);
  // Replaces box `index` with a valid box.
  void set_box(int index, const Box& box);
  // Replaces all colliders (every box valid) and rebuilds the index.
  void set_colliders(std::vector<Box> colliders);

  // Changes with every edit of the colliders (and differs between levels built separately):
  // a cache of query results (the animator's ground profile) is valid while it stays the same.
  std::uint64_t revision() const { return revision_; }

  // ---- Queries (inputs must be finite) ---------------------------------------------------
  // The ground below the x-span [x_min, x_max] (x_min <= x_max): the highest box top y with
  // from_y - max_drop <= y <= from_y + kGroundEpsilon among boxes whose x-range touches the
  // span (closed intervals). max_drop >= 0, metres. nullopt when nothing is in reach.
  std::optional<GroundHit> ground_height_below(float x_min, float x_max, float from_y,
                                               float max_drop) const;
  // Single point version: the span [x, x].
  std::optional<GroundHit> ground_height_below(float x, float from_y, float max_drop) const {
    return ground_height_below(x, x, from_y, max_drop);
  }

  // Does any collider's interior overlap `box`'s interior (touching does not count)?
  bool overlaps(const Box& box) const;
  // The lowest index of a collider overlapping `box`, or nullopt.
  std::optional<int> first_overlap(const Box& box) const;
  // Appends the indices of every collider overlapping `box` to `out`, in increasing order.
  void overlapping(const Box& box, std::vector<int>& out) const;

  // The first collider hit by `box` moved along `delta` (metres): smallest time of impact,
  // ties by lowest index. See sweep_against() in box.h for the exact contact rules.
  std::optional<SweepHit> sweep_box(const Box& box, glm::vec2 delta) const;
  // The first collider hit by the segment from `from_ws` to `to_ws` (a swept point): t is
  // the fraction of the segment, the hit point is from + t * (to - from).
  std::optional<SweepHit> raycast(glm::vec2 from_ws, glm::vec2 to_ws) const;
  // Is the point strictly inside a collider?
  bool point_inside(glm::vec2 p_ws) const { return overlaps(Box{p_ws, p_ws}); }
  // The lowest point at or straight above `p_ws` that is inside no collider (a point on a
  // box's bottom edge counts as inside): `p_ws` itself when it is free, else the top of the
  // box holding it (and of any box stacked on that).
  // A spawn inside a box stands on the first free ground above it (DESIGN.md §6).
  glm::vec2 free_point_above(glm::vec2 p_ws) const;
  // Is the spawn point inside a collider? (The level editor marks such a spawn.)
  bool spawn_inside_box() const { return free_point_above(spawn_ws) != spawn_ws; }
  // The kill height: kill_height_ws, else a margin below the lowest box (or below the spawn in
  // a level without boxes). The margin is kKillMargin, or kKillMarginOfHip times the hip height
  // of the creature asking when that is more (a creature a hundred times a horse's size is
  // not dead when its feet dip 2 m). O(1): the lowest box is the spatial index's root bound,
  // kept exact by every edit, so asking every tick costs nothing however many boxes there are.
  float kill_y(float hip_height_m = 0.0f) const;
  static constexpr float kKillMargin = 2.0f;       // metres
  static constexpr float kKillMarginOfHip = 1.0f;  // hip heights
  // Is there ground below the spawn point, above the kill height?
  bool spawn_has_ground() const;

  // Same name, spawn, background, look, kill height and colliders (in order).
  friend bool operator==(const Level& a, const Level& b) {
    return a.name == b.name && a.spawn_ws == b.spawn_ws && a.background == b.background && a.look == b.look &&
           a.kill_height_ws == b.kill_height_ws && a.colliders_ == b.colliders_;
  }

 private:
  void rebuild_index();

  std::vector<Box> colliders_;
  BoxTree index_;
  int refits_ = 0;  // set_box refits since the last rebuild
  std::uint64_t revision_ = 0;
};

// Deepest a point lies inside any collider (0 when outside or on a surface), metres.
float penetration_depth(const Level& level, glm::vec2 p_ws);
// Deepest any point of the segment a-b lies inside the colliders `boxes` (indices into the
// level), metres: exact, not sampled (inside a box the depth is the least distance to its four
// sides, concave along a segment, so its largest value lies at an end of the part of the
// segment inside the box or where two sides' distances meet).
float segment_penetration(const Level& level, glm::vec2 a_ws, glm::vec2 b_ws, const std::vector<int>& boxes);

}  // namespace ossa
