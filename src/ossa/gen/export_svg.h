#pragma once
// SVG export — a side view of a Creature in its rest pose (DESIGN.md §5.10), readable without
// GL in a browser or Inkscape, and a contact sheet of many creatures.
//
// Every bone is drawn as a bone-like shape in its own frame (origin at the joint with its
// parent, +x along the bone, length × width of the Skeleton) and placed by its model matrix
// through an SVG `transform="matrix(...)"`; the whole drawing is flipped once (SVG y points
// down, model y up). Shapes by BoneKind [Z 7.4, DESIGN.md §5.11]:
//   long bones    shaft with rounded joint knobs (two condyles at the distal end)
//   vertebrae     body with a dorsal spinous process and a small transverse process
//   ribs          curved, tapered arcs
//   skull         by variant: 0 mammal (cranium, snout, jaw), 1 bird (round cranium, beak),
//                 2 reptile (long flat head), 3 fish (pointed, with a gill arch)
//   scapula       a blade narrowing to the shoulder joint
//   pelvis        an ilium plate with the acetabulum at the hip joint
//   hand / foot   by limb: legs of winged creatures get a bird foot (three toes forward, one
//                 back); other legs a flat foot with ContactMode::kFlat or when the foot lies
//                 nearly flat in the rest pose, a hoof when the foot is steep and at least
//                 0.45 × the lower leg long (ungulate cannon bone), else a paw; arms a hand
//                 with three fingers; wings a long tapered wing hand; fins a fan
// Layers: Layer::kFar first in a darker fill, then kBody, then kNear [Z 7.1 step 5]. The
// ground (model y = 0) is drawn as a line over a soil strip; the viewBox fits the skeleton's
// bounds plus a margin. Bones with non-finite matrices or sizes are left out, so the output is
// always valid XML with finite numbers.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/creature.h"

namespace ossa {

// A body drawn as SVG by body/body_svg.h, one group's content per Layer, in model coordinates
// (y up, as the bones), and its bounds. export_svg draws each layer's bones, then its body.
struct SvgBody {
  std::array<std::string, 3> layers;
  glm::vec2 lo{0.0f}, hi{0.0f};
  float opacity = 1.0f;        // < 1: translucent over the bones (the x-ray look)
};

struct SvgOptions {
  int width_px = 800;          // output width in pixels; the height follows the aspect
  float margin = 0.06f;        // margin around the bounds, as a fraction of the larger extent
  // Skull shape: 0 mammal, 1 bird, 2 reptile, 3 fish (Genome::skull_variant). -1 chooses by
  // the creature: bird skull for winged creatures, fish for legless wingless ones with fins,
  // reptile for a long flat skull (length > 2.6 × width), else mammal.
  int skull_variant = -1;
  bool ground = true;          // draw the ground line at y = 0
  bool title = true;           // write the creature's name as <title>
  bool bones = true;           // draw the bones (false: the body alone)
  const SvgBody* body = nullptr;  // the creature's body, drawn with the bones as above
};

// A complete SVG document (UTF-8) of `creature` in its rest pose.
std::string creature_svg(const Creature& creature, const SvgOptions& options = {});

// A grid of creatures, `columns` per row (clamped to >= 1), each scaled to its cell keeping
// its aspect ratio, with its name written below (escaped). Each creature is drawn with
// `options` (skull_variant -1 unless a per-creature variant is given in `skull_variants`,
// which is either empty or one entry per creature).
// `bodies` is empty or one per creature (then each cell draws its body, options.body ignored).
std::string sheet_svg(const std::vector<std::pair<std::string, Creature>>& creatures,
                      int columns, const std::vector<int>& skull_variants = {},
                      const SvgOptions& options = {}, const std::vector<SvgBody>& bodies = {});

// `text` with &, <, >, " and ' replaced by XML entities.
std::string xml_escape(const std::string& text);

}  // namespace ossa
