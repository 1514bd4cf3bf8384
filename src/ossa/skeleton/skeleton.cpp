#include "ossa/skeleton/skeleton.h"

#include <cmath>

#include "ossa/assert.h"

namespace ossa {

const char* bone_kind_name(BoneKind kind) {
  switch (kind) {
    case BoneKind::kRoot: return "root";
    case BoneKind::kSkull: return "skull";
    case BoneKind::kNeckVertebra: return "neck_vertebra";
    case BoneKind::kBackVertebra: return "back_vertebra";
    case BoneKind::kTailVertebra: return "tail_vertebra";
    case BoneKind::kRib: return "rib";
    case BoneKind::kScapula: return "scapula";
    case BoneKind::kPelvis: return "pelvis";
    case BoneKind::kUpperLimb: return "upper_limb";
    case BoneKind::kLowerLimb: return "lower_limb";
    case BoneKind::kHand: return "hand";
  }
  return "unknown";
}

const char* layer_name(Layer layer) {
  switch (layer) {
    case Layer::kFar: return "far";
    case Layer::kBody: return "body";
    case Layer::kNear: return "near";
  }
  return "unknown";
}

int Skeleton::add_bone(std::string name, BoneKind kind, int parent, float length, float width,
                       BoneLocal rest, Layer layer) {
  OSSA_ASSERT(parent == kNoParent || (parent >= 0 && parent < bone_count()),
              "parent must be added before its child");
  OSSA_ASSERT(parent != kNoParent || bone_count() == 0, "only the first bone may be a root");
  parents_.push_back(parent);
  names_.push_back(std::move(name));
  kinds_.push_back(kind);
  lengths_.push_back(length);
  widths_.push_back(width);
  layers_.push_back(layer);
  rest_.push_back(rest);
  flip_y_.push_back(0);
  return bone_count() - 1;
}

int Skeleton::find(std::string_view name) const {
  for (int i = 0; i < bone_count(); ++i) {
    if (names_[i] == name) return i;
  }
  return -1;
}

int Skeleton::count(BoneKind kind) const {
  int n = 0;
  for (BoneKind k : kinds_) n += (k == kind);
  return n;
}

bool Skeleton::is_valid() const {
  for (int i = 0; i < bone_count(); ++i) {
    if (i == 0 ? parents_[i] != kNoParent : (parents_[i] < 0 || parents_[i] >= i)) return false;
    if (!std::isfinite(lengths_[i]) || lengths_[i] < 0.0f) return false;
    if (!std::isfinite(widths_[i]) || widths_[i] < 0.0f) return false;
    if (!std::isfinite(rest_[i].offset_ls.x) || !std::isfinite(rest_[i].offset_ls.y) ||
        !std::isfinite(rest_[i].angle_ls)) {
      return false;
    }
  }
  return true;
}

}  // namespace ossa
