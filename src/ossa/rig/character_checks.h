#pragma once
// Plausibility checks of build_character (character.h) on a rig's legs, apart from the build
// itself: what the animator cannot use is refused, what is probably a mistake is reported in
// Character::warnings (ossa-rig check prints them as problems). Not a public interface.

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/io/result.h"
#include "ossa/rig/rig_mapping.h"

namespace ossa {

// A foot (ankle to contact point) longer than this many legs (upper + lower) is refused: the
// contact point sizes the foot, and with it the ground the animator samples around the
// creature and where its planner looks, so a contact point far away must not pass
// ([1e6, -1e6] grew the ground profile until bad_alloc). One longer than kLongFootOfLeg legs is
// reported.
inline constexpr float kMaxFootOfLeg = 2.0f;
inline constexpr float kLongFootOfLeg = 1.0f;
// Legs (upper + lower) outside this range, metres, are reported: a mesh in the wrong unit.
inline constexpr float kMinLegMetres = 0.01f;
inline constexpr float kMaxLegMetres = 20.0f;
// The animator's gaits are written for one to three leg pairs (bipeds, quadrupeds, six legs).
inline constexpr int kMaxPlausibleLegPairs = 3;

// Leg `path` ("legs[0]") whose foot bone `foot` runs from `ankle_ms` to `contact_ms`, with
// `reach_m` = upper + lower (ossa model space, metres): an Error naming `file` and
// "<path>.contact" for a contact beyond kMaxFootOfLeg legs; warnings for a long foot or a leg
// outside [kMinLegMetres, kMaxLegMetres].
Status check_leg_size(const std::string& path, const std::string& foot, glm::vec2 ankle_ms, glm::vec2 contact_ms,
                      float reach_m, const std::string& file, std::vector<std::string>& warnings);

// A warning when the mapping has more than kMaxPlausibleLegPairs leg pairs.
void check_leg_pairs(const RigMapping& mapping, std::vector<std::string>& warnings);

}  // namespace ossa
