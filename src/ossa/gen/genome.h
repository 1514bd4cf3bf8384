#pragma once
// Genome — everything needed to rebuild one creature's skeleton exactly, without drawing a
// random number [Z 8.1]: the PCA point in original units, the discrete choices the generator
// made (vertebra counts, rib interval, limbs and their rest angles, contact mode, skull), the
// scale and the options. Saved as versioned JSON (`.creature.json`):
//
//   { "format": "ossa.creature", "version": 1, "name": "horse", "seed": 42,
//     "pca": { "wings": 0, "leg_pairs": 2, "weight_kg": 500, "spine[0].x": 812.0, ... },
//     "vertebrae": { "neck": 7, "back": 25, "tail": 18 }, "rib_interval": 0.62,
//     "limbs": [ { "kind": "leg", "girdle": "shoulder", "slot": 0,
//                  "angles": [-1.9, 0.4, -0.5] }, ... ],
//     "contact": "tip", "skull": 0, "size": "true", "scale": 0.0031,
//     "options": { "arc_length_vertebrae": true, "neck_girdle": false, "multi_limb": false,
//                  "smooth_skinning": true },
//     "gait_family": "auto",
//     "look": { "base": "#8a5a3c", "belly": "#d8c3a0", "pattern": "none", ... },
//     "appendages": [ { "kind": "ears", "size": 1 }, { "kind": "mane", "size": 1 } ] }
//
// `size` is the size choice: "true" (the animal's size from its weight and body plan,
// gen/true_size.h) or a number, a fixed frame in metres (stylised games: every creature in the
// same frame). `scale` is the metres per frame unit the choice gave when the genome was made;
// tools build the creature at `scale` as saved (Generator::apply_size makes it again). Files
// without `size` (before true size) keep their scale: "size" is then the frame their scale
// gives, or "true" if their options said "true_size": true.
//
// `gait_family` (gen/gait_family.h) is how the creature moves: "auto" (chosen from the body
// plan when the animator's rig is built) or a family's name. Files without it get "auto".
//
// Version 2 added `look` and `appendages` (gen/look.h: the body's coat, fatness, wing cover and
// optional parts; they change no bone). Version 1 files still load: their look is drawn from
// their seed (random_look) and they have no appendages.
//
// `pca` holds the 29 dimensions of gen/dataset.h by their dim_name(). `angles` are the rest
// pose of the limb chain: the upper bone's absolute angle in model space, then the lower bone
// and hand/foot relative to their parent (radians), for the near copy; the far copy mirrors
// nothing (it is the same limb seen from the other side) and reuses them.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ossa/gen/creature.h"
#include "ossa/gen/dataset.h"
#include "ossa/gen/look.h"
#include "ossa/gen/skull_shape.h"
#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"

namespace ossa {

struct GenomeOptions {
  bool arc_length_vertebrae = true;  // false: the thesis's t = i/n spacing [Z 7.3]
  bool neck_girdle = false;          // a girdle just below the head (centaur) [Z 7.2.3]
  bool multi_limb = false;           // two limb slots per girdle (pegasus) [Z 7.2.3]
  bool true_size = true;             // the size choice: the animal's true size from its weight
                                     // and body plan (gen/true_size.h), else a fixed frame …
  float frame_m = 2.0f;              // … this many metres across (the skeleton's 1000 frame
                                     // units; 2 m: every creature as big as a pony)
  bool smooth_skinning = true;       // bone sprites blend parent and child near each joint, so a
                                     // bent knee keeps one outline (draw/sprite_mesh.h); false:
                                     // every sprite follows its own bone rigidly. Files without
                                     // the key (older ones) get true. Changes no bone.
};


struct LimbGene {
  LimbKind kind = LimbKind::kLeg;
  GirdleKind girdle = GirdleKind::kShoulder;
  int slot = 0;                              // 0, or 1 with multi_limb
  std::array<float, 3> angles{};             // rest pose, see above (radians)
};

struct Genome {
  static constexpr int kVersion = 2;         // 2: look and appendages; 1 still loads

  std::string name;                          // example name or "random"
  uint64_t seed = 0;                         // the seed the choices were drawn from (info only)
  std::array<double, kPcaDims> pca{};        // raw units (frame units, kg, 0/1, 0..2)
  int neck_vertebrae = 7;                    // [Z 7.3]: 7, winged 10–30
  int back_vertebrae = 25;                   // 13 in front of the root, 12 behind
  int tail_vertebrae = 10;                   // 5–20 (0 when the tail has no length)
  float rib_interval = 0.6f;                 // ribs on back vertebrae in [0, x] of the back arc
                                             // from the shoulder, x in [0, 1]
  std::vector<LimbGene> limbs;               // one per limb pair
  ContactMode contact = ContactMode::kTip;
  int skull_variant = 0;                     // 0 mammal, 1 bird, 2 reptile, 3 fish
  SkullShape skull_shape;                    // its proportions (default: the variant's)
  float scale = 0.002f;                      // metres per frame unit
  GenomeOptions options;
  GaitFamily gait_family = GaitFamily::kAuto;  // how it moves; kAuto: from the body plan
  Look look;                                 // the body's coat, fatness, wing cover (gen/look.h)
  std::vector<Appendage> appendages;         // ears, horns, mane … (at most one of each kind)
};

constexpr int kSkullVariants = 4;

// ---- What a genome file may hold (the loader's ranges) ------------------------------------
// The generator clamps what it writes into the same ranges (clamp_to_genome_limits), so every
// file a tool writes loads back, and everything the loader accepts builds, animates and
// renders (issue 17's one rule; the fuzz_creature target checks it).
//   pca: spine points in [-1000, 2000] frame units (one frame either side of the 1000 × 1000
//   frame), limb lengths in [0, 1000], wings in [-1, 2], leg_pairs in [-1, 3], weight_kg in
//   [0.001, 1 000 000]; vertebrae neck 0–32, back 2–32, tail 0–32; scale in [5e-5, 0.05]
//   metres per frame unit (a 5 cm to a 50 m frame: the smallest example, 0.01 kg, at true
//   size is 5.4e-5).
inline constexpr int kMaxNeckVertebrae = 32;
inline constexpr int kMaxBackVertebrae = 32;
inline constexpr int kMaxTailVertebrae = 32;
inline constexpr int kMaxLimbPairs = 6;  // 3 girdles × 2 slots
inline constexpr float kMinGenomeScale = 5e-5f;
inline constexpr float kMaxGenomeScale = 0.05f;
inline constexpr float kMinFrameMetres = 0.05f;   // a fixed frame: 5 cm …
inline constexpr float kMaxFrameMetres = 50.0f;   // … to 50 m (the scale's range)
// The most bones a genome within these limits builds: root, skull, every vertebra, two ribs
// per back vertebra, and per limb pair and side a girdle bone and three limb bones.
inline constexpr int kMaxCreatureBones =
    2 + kMaxNeckVertebrae + kMaxBackVertebrae + kMaxTailVertebrae + 2 * kMaxBackVertebrae + kMaxLimbPairs * 2 * 4;
struct PcaRange {
  double min, max;
};
PcaRange pca_range(int dim);
// Clamps every field into the ranges above (NaN becomes the range's low end), the look and
// appendages into theirs (gen/look.h).
void clamp_to_genome_limits(Genome& genome);
const char* skull_variant_name(int variant);

// ---- The size choice on a command line (--size of ossa-gen, ossa-sim, ossa-render, ossa) ---
// "true" (the animal's true size, gen/true_size.h) or a frame in metres in [kMinFrameMetres,
// kMaxFrameMetres], as the genome file's "size" holds it.
struct SizeChoice {
  bool true_size = true;
  float frame_m = 2.0f;  // with true_size false
  // Sets the choice in `options` (GenerateOptions::genome, or a loaded genome's options: then
  // Generator::apply_size(genome) makes its scale again). True size keeps the options' frame.
  void apply_to(GenomeOptions& options) const {
    options.true_size = true_size;
    if (!true_size) options.frame_m = frame_m;
  }
};
// `text` as a size choice, or an error naming `flag`, what it takes and what was given:
// "--size: expected true or a frame in metres (a number in [0.05, 50]), got \"big\"".
Result<SizeChoice> parse_size_arg(std::string_view flag, std::string_view text);

Json genome_to_json(const Genome& genome);
// Parses and validates (every accepted genome builds: build_creature succeeds); errors name
// the file and field.
Result<Genome> genome_from_json(const Json& doc, std::string_view file);
Result<Genome> parse_genome(std::string_view text, std::string_view file);
Result<Genome> load_genome(const std::string& path);
Status save_genome(const std::string& path, const Genome& genome);  // atomic

}  // namespace ossa
