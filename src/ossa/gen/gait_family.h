#pragma once
// GaitFamily — how a body plan moves (../shared/GAITS.md, "Repertoires by body plan"): its
// gaits, where they change and how fast it can go. A genome stores its choice ("gait_family",
// default "auto": chosen from the body plan by anim::choose_gait_family); the animator reads
// what each family does from anim::gait_family_traits (anim/gait_family.h).

#include <cstdint>
#include <string_view>

namespace ossa {

enum class GaitFamily : uint8_t {
  kAuto,         // chosen from the body plan
  kCursorial,    // lateral-sequence walk → trot → transverse gallop (horse, deer, dog)
  kPacer,        // lateral-sequence walk → pace (lateral pairs) → rotary gallop (camel, giraffe)
  kGraviportal,  // lateral-sequence walk and amble at every speed, never airborne (elephant)
  kBounder,      // walk → half-bound → bound, the spine flexing (rabbit, hyrax)
  kHopper,       // both hind feet in phase at every speed (kangaroo, frog)
  kSprawler,     // diagonal-couplet walk → trot, no gallop above 5 kg (lizards, crocodiles)
  kBiped,        // walk → run, the legs alternating
  kBird,         // walk → grounded run → aerial run; small birds bob their heads
  kMultiLeg,     // three or more leg pairs: a metachronal wave
  kLegless,      // no legs: a travelling wave along the body
};
inline constexpr int kGaitFamilyCount = 11;

// "auto", "cursorial", "pacer", "graviportal", "bounder", "hopper", "sprawler", "biped",
// "bird", "multi_leg", "legless".
const char* gait_family_name(GaitFamily family);
// The family named `name`; false when no family has that name.
bool parse_gait_family(std::string_view name, GaitFamily* family);

}  // namespace ossa
