#include "ossa/rig/character_checks.h"

#include <algorithm>
#include <cstdio>

#include <glm/geometric.hpp>

#include "ossa/io/json.h"

namespace ossa {

Status check_leg_size(const std::string& path, const std::string& foot, glm::vec2 ankle_ms, glm::vec2 contact_ms,
                      float reach_m, const std::string& file, std::vector<std::string>& warnings) {
  const std::string quoted = "\"" + foot + "\"";
  const float length = glm::length(contact_ms - ankle_ms);
  char what[320];
  if (!(length <= kMaxFootOfLeg * reach_m)) {
    std::snprintf(what, sizeof what,
                  "the contact point of foot %s lies %.3g m from its ankle, more than %g times the leg's length (%.3g m): "
                  "expected a point on the sole",
                  quoted.c_str(), double(length), double(kMaxFootOfLeg), double(reach_m));
    return Error::at(file, json_path(path, "contact"), what);
  }
  if (length > kLongFootOfLeg * reach_m) {
    std::snprintf(what, sizeof what, "%s: the contact point of foot %s lies %.3g m from its ankle, further than the leg is long (%.3g m)",
                  path.c_str(), quoted.c_str(), double(length), double(reach_m));
    warnings.push_back(what);
  }
  if (reach_m < kMinLegMetres || reach_m > kMaxLegMetres) {
    std::snprintf(what, sizeof what,
                  "%s: the leg is %.3g m long (upper + lower), outside the %g m to %g m of walking animals: is \"scale\" "
                  "right? (a mesh in centimetres needs 0.01)",
                  path.c_str(), double(reach_m), double(kMinLegMetres), double(kMaxLegMetres));
    warnings.push_back(what);
  }
  return {};
}

void check_leg_pairs(const RigMapping& mapping, std::vector<std::string>& warnings) {
  std::vector<int> pairs;
  for (size_t i = 0; i < mapping.legs.size(); ++i) pairs.push_back(mapping.leg_pair(i));
  std::sort(pairs.begin(), pairs.end());
  const long n = std::unique(pairs.begin(), pairs.end()) - pairs.begin();
  if (n <= kMaxPlausibleLegPairs) return;
  char what[240];
  std::snprintf(what, sizeof what,
                "legs: %ld leg pairs; the animator's gaits are made for 1 to %d (bipeds, quadrupeds, six legs): more "
                "walk, but their feet slide on steps",
                n, kMaxPlausibleLegPairs);
  warnings.push_back(what);
}

}  // namespace ossa
