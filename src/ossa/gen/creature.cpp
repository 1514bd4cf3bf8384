#include "ossa/gen/creature.h"

#include "ossa/gen/gait_family.h"

namespace ossa {

const char* limb_kind_name(LimbKind kind) {
  switch (kind) {
    case LimbKind::kLeg: return "leg";
    case LimbKind::kArm: return "arm";
    case LimbKind::kWing: return "wing";
    case LimbKind::kFin: return "fin";
  }
  return "unknown";
}

const char* girdle_kind_name(GirdleKind kind) {
  switch (kind) {
    case GirdleKind::kNeck: return "neck";
    case GirdleKind::kShoulder: return "shoulder";
    case GirdleKind::kHip: return "hip";
  }
  return "unknown";
}

const char* contact_mode_name(ContactMode mode) {
  return mode == ContactMode::kFlat ? "flat" : "tip";
}

const char* gait_family_name(GaitFamily family) {
  switch (family) {
    case GaitFamily::kAuto: return "auto";
    case GaitFamily::kCursorial: return "cursorial";
    case GaitFamily::kPacer: return "pacer";
    case GaitFamily::kGraviportal: return "graviportal";
    case GaitFamily::kBounder: return "bounder";
    case GaitFamily::kHopper: return "hopper";
    case GaitFamily::kSprawler: return "sprawler";
    case GaitFamily::kBiped: return "biped";
    case GaitFamily::kBird: return "bird";
    case GaitFamily::kMultiLeg: return "multi_leg";
    case GaitFamily::kLegless: return "legless";
  }
  return "unknown";
}

bool parse_gait_family(std::string_view name, GaitFamily* family) {
  for (int i = 0; i < kGaitFamilyCount; ++i) {
    const auto f = static_cast<GaitFamily>(i);
    if (name == gait_family_name(f)) {
      *family = f;
      return true;
    }
  }
  return false;
}

int Creature::leg_count() const { return count(LimbKind::kLeg); }

int Creature::count(LimbKind kind) const {
  int n = 0;
  for (const Limb& l : limbs) n += (l.kind == kind);
  return n;
}

}  // namespace ossa
