#pragma once
// Dataset — the example animals the PCA model learns from ([Z 6.1], DESIGN.md §5.1).
//
// File: assets/creatures/examples.json (format "ossa.examples", version 1). Every animal is a
// side view in the 1000×1000 frame of [Z 9.6]: origin bottom-left, +y up, the animal facing +x
// (head on the right), its skeleton's bounding box cropped, scaled to fit and set on the bottom
// edge, centred in x. All coordinates and lengths below are in these frame units.
//
//   {"format": "ossa.examples", "version": 1,
//    "frame": {"width": 1000, "height": 1000, "origin": "bottom-left", "facing": "+x"},
//    "source": "...",
//    "animals": [
//      {"name": "horse", "name_de": "Pferd", "class": "mammal", "wings": 0, "leg_pairs": 2,
//       "weight_kg": 600, "spine": [[x, y] × 10],
//       "front": {"upper": .., "lower": .., "hand": ..},
//       "hind": {"upper": .., "lower": .., "foot": ..},
//       "posture": "unguligrade",   (optional: "unguligrade", "digitigrade" or "plantigrade")
//       "note": "optional free text",
//       "skull": {"length": 0.5, "height": 0.36, "snout": 0.62},   (optional, skull_shape.h)
//       "look": {...}, "appendages": [...]}, ...]}     (optional: the body, gen/look.h)
//
// Each animal is also a point of the 29-dimensional raw vector space the PCA works in
// (to_vector / from_vector in pca_model.h, layout in `Dim`).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/gen/look.h"
#include "ossa/gen/skull_shape.h"
#include "ossa/io/result.h"

namespace ossa {

// Index of the named points in Animal::spine. The spine is three cubic Béziers sharing their
// end points: neck = spine[0..3] (head end → shoulder), back = spine[3..6] (shoulder → hip),
// tail = spine[6..9] (hip → tail tip). A missing neck repeats the shoulder point four times, a
// missing tail repeats the hip point ([Z 6.1]).
inline constexpr int kSpineHead = 0;      // head end of the neck (where the skull sits)
inline constexpr int kSpineShoulder = 3;  // neck/back junction (shoulder girdle)
inline constexpr int kSpineHip = 6;       // back/tail junction (pelvic girdle)
inline constexpr int kSpineTailTip = 9;   // end of the tail
inline constexpr int kSpinePoints = 10;

// Bone lengths of one limb in frame units; 0 when the limb (or the bone) is absent.
struct LimbLengths {
  double upper = 0.0;   // humerus / femur (birds' wing: humerus)
  double lower = 0.0;   // radius+ulna / tibia (birds' wing: ulna/radius)
  double distal = 0.0;  // hand (front, file key "hand") / foot (hind, file key "foot")

  double total() const { return upper + lower + distal; }
};

// How an animal's legs meet the ground (GAITS.md "Limb posture"): on hooves at the tip of a
// long metapodial, on its toes, or on the whole sole. The skeleton has one foot bone, so the
// first two stand on its tip (ContactMode::kTip) and the third on the whole bone (kFlat).
enum class LimbPosture : uint8_t { kUnguligrade, kDigitigrade, kPlantigrade };
const char* limb_posture_name(LimbPosture posture);

struct Animal {
  std::string name;          // English, lower case, unique ("horse")
  std::string name_de;       // German as in [Z] ("Pferd")
  std::string animal_class;  // "mammal", "bird", "reptile", "amphibian", "fish", "dinosaur"
  int wings = 0;             // 0 or 1
  int leg_pairs = 0;         // pairs of legs with ground contact: 0, 1 or 2 [Z 6.1]
  double weight_kg = 0.0;    // adult weight, >= 0
  std::array<glm::vec2, kSpinePoints> spine{};  // frame units, see kSpineHead..kSpineTailTip
  LimbLengths front;         // upper arm, forearm, hand (birds: the wing)
  LimbLengths hind;          // thigh, shank, foot
  std::optional<LimbPosture> posture;  // how its legs stand (else from their proportions)
  std::optional<SkullShape> skull;  // the skull's proportions (else its class's default)
  std::optional<Look> look;  // the body's coat (else drawn from the genome's seed)
  std::vector<Appendage> appendages;  // ears, horns, mane … the animal has
};

struct Dataset {
  std::vector<Animal> animals;

  // The animal whose English or German name equals `name_en_or_de`, ignoring ASCII case
  // ("Horse", "PFERD"; umlauts must match exactly); nullptr if none.
  const Animal* find(std::string_view name_en_or_de) const;
};

// Parses an examples file. `file` names the source in error messages. Every field is checked;
// errors name the animal and the field, e.g.
//   examples.json: animals[3] (giraffe).spine[2]: expected a point [x, y] with 0 <= x, y <= 1000, got [12, 1200]
// Names (English and German, case-insensitively) must be unique across the file.
Result<Dataset> parse_dataset(std::string_view text, std::string_view file);
// Reads and parses `path`; errors name the path.
Result<Dataset> load_dataset(const std::string& path);

// ---------------------------------------------------------------------------------------
// The raw 29-dimensional vector [Z 6.1] (original units: counts, kg, frame units).
inline constexpr int kPcaDims = 29;

// Index layout of the raw vector (PcaVector, pca_model.h).
enum Dim : int {
  kWings = 0,     // 0..1 (samples are continuous: a probability-like value)
  kLegPairs = 1,  // 0..2 (samples are continuous)
  kWeightKg = 2,  // kg
  kSpine0X = 3,   // spine[i].x = kSpine0X + 2*i, spine[i].y = kSpine0X + 2*i + 1 (i = 0..9)
  kSpine9Y = 22,
  kFrontUpper = 23,
  kFrontLower = 24,
  kFrontHand = 25,
  kHindUpper = 26,
  kHindLower = 27,
  kHindFoot = 28,
};
constexpr int spine_x_dim(int point) { return kSpine0X + 2 * point; }
constexpr int spine_y_dim(int point) { return kSpine0X + 2 * point + 1; }

// Name of a dimension: "wings", "leg_pairs", "weight_kg", "spine[3].x", "front.upper",
// "front.hand", "hind.foot". Requires 0 <= dim < kPcaDims.
const char* dim_name(int dim);
// The dimension called `name` (as dim_name spells it), or -1.
int dim_from_name(std::string_view name);

}  // namespace ossa
