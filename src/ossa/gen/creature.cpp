#include "ossa/gen/creature.h"

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

int Creature::leg_count() const { return count(LimbKind::kLeg); }

int Creature::count(LimbKind kind) const {
  int n = 0;
  for (const Limb& l : limbs) n += (l.kind == kind);
  return n;
}

}  // namespace ossa
