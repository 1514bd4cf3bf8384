#pragma once
// Look — how a creature's body is dressed (issue 30, DESIGN.md §9): its coat (base colour,
// countershading, an optional pattern), how fat it is, what its wings are made of, and its
// optional appendages (ears, horns, a frill, a mane …). Part of the Genome (`"look"` and
// `"appendages"` in a `.creature.json`, version 2); the body builder (body/body_mesh.h) reads
// it from the Creature. Changes no bone.
//
//   "look": {"base": "#8a5a3c", "belly": "#d9c4a5", "pattern": "spots",
//            "pattern_colour": "#3a2a1c", "pattern_scale": 0.12, "fatness": 1.0,
//            "wings": "feathered"},
//   "appendages": [{"kind": "ears", "size": 1.0}, {"kind": "mane", "size": 0.8}]
//
// Colours are sRGB "#rrggbb". Ranges (the loader refuses anything else, naming file and
// field): pattern_scale 0.02 … 1 (the pattern's cell size as a fraction of the back length),
// fatness 0.6 … 1.6 (a factor on the body mass the weight asks for: 1 = the genome's weight at
// the creature's size), appendage size 0.25 … 3 (a factor on the kind's default size for the
// body), at most one appendage of each kind.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "ossa/io/json_fwd.h"

namespace ossa {

// Coat patterns, drawn from seeded noise in body coordinates (body/coat.h).
enum class CoatPattern : uint8_t { kNone, kStripes, kSpots, kRosettes, kDapples, kPatches };
inline constexpr int kCoatPatternCount = 6;
// What a wing's outline is made of: flight feathers trailing the wing bones (birds), or a
// membrane from the wing's tip back to the body (bats, pterosaurs).
enum class WingCover : uint8_t { kFeathered, kMembrane };

enum class AppendageKind : uint8_t {
  kEars,       // on the skull, behind the eye (near ear in front of the head, far ear behind)
  kHorns,      // curved horns from the top of the skull (bovids; triceratops brow horns)
  kAntlers,    // branched antlers from the top of the skull (deer)
  kFrill,      // a bony shield behind the skull (ceratopsians)
  kCrest,      // a crest on the skull (parasaurolophus, birds, the chameleon's casque)
  kMane,       // hair along the top of the neck (horse, wildebeest, giraffe)
  kTrunk,      // a proboscis hanging from the snout (elephant)
  kHump,       // a fat hump over the back (dromedary)
  kSail,       // a sail of long spines along the back (dimetrodon)
  kPlates,     // upright plates along the back and tail (stegosaurus)
  kShell,      // a domed shell over the trunk (tortoise)
  kDorsalFin,  // a fin on the back (fish, dolphins, ichthyosaurs)
  kTailFin,    // a caudal fin or fluke at the tail's tip (fish, whales, ichthyosaurs)
};
inline constexpr int kAppendageKindCount = 13;
const char* appendage_kind_name(AppendageKind kind);
std::optional<AppendageKind> appendage_kind_from_name(std::string_view name);
const char* coat_pattern_name(CoatPattern pattern);
std::optional<CoatPattern> coat_pattern_from_name(std::string_view name);
const char* wing_cover_name(WingCover cover);

struct Appendage {
  AppendageKind kind = AppendageKind::kEars;
  float size = 1.0f;  // factor on the kind's default size for this body, 0.25 … 3
};

inline constexpr float kMinPatternScale = 0.02f, kMaxPatternScale = 1.0f;
inline constexpr float kMinFatness = 0.6f, kMaxFatness = 1.6f;
inline constexpr float kMinAppendageSize = 0.25f, kMaxAppendageSize = 3.0f;

struct Look {
  glm::vec3 base{0.55f, 0.42f, 0.30f};     // sRGB 0…1: the coat on the flanks
  glm::vec3 belly{0.85f, 0.78f, 0.66f};    // sRGB: the underside (countershading); the back
                                           // is drawn darker than base (coat.h)
  CoatPattern pattern = CoatPattern::kNone;
  glm::vec3 pattern_colour{0.2f, 0.15f, 0.1f};  // sRGB
  float pattern_scale = 0.12f;             // pattern cell size / back length
  float fatness = 1.0f;                    // factor on the weight's body mass
  WingCover wings = WingCover::kFeathered;

  bool operator==(const Look&) const = default;
};

// A plausible look drawn from `seed` for a body of the given kind: mammals in browns, greys
// and tans (sometimes striped, spotted or dappled), birds in greys, browns, black and white,
// reptiles in olives and browns, fish silvery blue-grey; bellies lighter; fatness 0.9 … 1.1.
// `skull_variant` as Genome::skull_variant (0 mammal, 1 bird, 2 reptile, 3 fish).
Look random_look(uint64_t seed, int skull_variant, bool winged);

// "#rrggbb" (lower case) of an sRGB colour (clamped to 0…1, rounded).
std::string colour_hex(glm::vec3 colour);
// The colour "#rrggbb" (either case) names, or nullopt.
std::optional<glm::vec3> colour_from_hex(std::string_view text);

Json look_to_json(const Look& look);
Json appendages_to_json(const std::vector<Appendage>& appendages);
// Read `parent[key]` as a look / an appendage list into `out`, recording the first error in
// `r` (file and field path, e.g. `x.creature.json: look.fatness: expected a number in
// [0.6, 1.6], got 3`). `path` is the parent's path ("" for the document).
void read_look(JsonReader& r, const Json& parent, std::string_view path, std::string_view key, Look& out);
void read_appendages(JsonReader& r, const Json& parent, std::string_view path, std::string_view key,
                     std::vector<Appendage>& out);

// Clamps every field of a look or an appendage list into its range (NaN to the low end) and
// keeps the first appendage of each kind.
void clamp_look(Look& look);
void clamp_appendages(std::vector<Appendage>& appendages);

}  // namespace ossa
