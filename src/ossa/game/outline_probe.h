#pragma once
// The drawn body against the level (issue 27: "where a creature has a body outline, for the
// outline too"). SimProbe measures the bones; the body the game draws around them (body_mesh.h)
// has flesh, horns, fins and flukes beyond the bones. An OutlineProbe skins that body by the
// animator's matrices as the body shader does, rests it on the floor the game sends with it
// (body_floor.h: flesh yields to the box tops under the creature), and measures how deep any
// part's closed outline lies inside a collider: every segment between two consecutive outline
// vertices, exactly (segment_penetration). Fills lie inside their outlines; the outline
// strokes' width is left out, and so is a collider lying wholly inside a part's fill with no
// outline segment crossing it (a thin post the body is drawn over): the figure is the
// outline's depth in the level, not the level's depth in the body.
//
// Apart from SimProbe because it costs a body mesh per creature and a skinning per tick:
// ossa-sim and ossa-sweep report it; the animation tests, which gate on the bones, do not pay
// for it. A rigged character (character.h) has no generated body and no OutlineProbe.

#include <array>
#include <string>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/body/body_mesh.h"
#include "ossa/gen/creature.h"
#include "ossa/level/level.h"

namespace ossa {

class OutlineProbe {
 public:
  // Builds `creature`'s body (build_body with its own look and girth).
  explicit OutlineProbe(const Creature& creature);
  // After a tick: `animator` posed over `level`, `t_s` seconds since the start.
  void observe(const Animator& animator, const Level& level, float t_s);

  // The deepest any drawn outline lay inside a collider, metres; the part it belonged to
  // (body_part_name: "axial", "leg", "tail_fin" …) and when.
  float max_outline_penetration_m = 0.0f;
  std::string deepest_outline_part;
  float deepest_outline_at_s = 0.0f;
  // The same per kind of part (indexed by BodyPartKind): how deep a whale's flukes went.
  std::array<float, kBodyPartKindCount> max_by_kind{};

  // Every part's closed outline as observe() last drew it (world metres), in draw order: the
  // strobe pictures draw them (ossa-sim --svg).
  std::vector<std::vector<glm::vec2>> drawn_outlines() const;

 private:
  BodyMesh mesh_;
  std::vector<Mat2x3> palette_;
  std::vector<glm::vec2> drawn_;  // per vertex, as drawn this tick (outline vertices only)
  std::vector<int> hits_;
};

}  // namespace ossa
