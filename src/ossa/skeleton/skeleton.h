#pragma once
// Skeleton — the shared, immutable runtime description of a creature's bones (ozz/Jolt style:
// flat arrays, parents stored before children). Built once by gen::SkeletonBuilder (or by
// hand in tests); each creature instance animates its own Pose (pose.h).
//
// Space and units: lengths and offsets are metres in creature ("model") space, +x forward
// (the creature faces +x), +y up. A bone's local frame has its origin at the joint with its
// parent and its +x axis along the bone; the bone ends at (length, 0) in that frame.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

namespace ossa {

// What a bone is, anatomically; drives sprite choice and animation roles.
enum class BoneKind : uint8_t {
  kRoot,          // zero-length bone at mid-back [Z 5.1]
  kSkull,
  kNeckVertebra,
  kBackVertebra,
  kTailVertebra,
  kRib,
  kScapula,       // shoulder (or neck) girdle bone
  kPelvis,        // hip girdle bone
  kUpperLimb,     // humerus / femur / wing humerus / fin base
  kLowerLimb,     // forearm / shank / wing forearm
  kHand,          // hand / foot / wing hand / fin tip
};
const char* bone_kind_name(BoneKind kind);

// Draw layer: the far copy of paired bones is drawn behind the body (and darker), the near
// copy in front of it [Z 7.1 step 5].
enum class Layer : uint8_t { kFar = 0, kBody = 1, kNear = 2 };
constexpr int kLayerCount = 3;
const char* layer_name(Layer layer);

// A joint in the parent's frame: where the child bone starts, and its rotation relative to
// the parent. For the root the offset is the root's position in model space.
struct BoneLocal {
  glm::vec2 offset_ls{0.0f, 0.0f};  // metres, parent-local
  float angle_ls = 0.0f;            // radians, counter-clockwise, relative to the parent
};

// Sentinel parent index of the root bone.
constexpr int kNoParent = -1;

class Skeleton {
 public:
  // Appends a bone and returns its index. The parent must already exist (parents first).
  int add_bone(std::string name, BoneKind kind, int parent, float length, float width,
               BoneLocal rest, Layer layer);

  int bone_count() const { return static_cast<int>(parents_.size()); }
  int parent(int bone) const { return parents_[bone]; }
  const std::string& name(int bone) const { return names_[bone]; }
  BoneKind kind(int bone) const { return kinds_[bone]; }
  float length(int bone) const { return lengths_[bone]; }  // metres
  float width(int bone) const { return widths_[bone]; }    // metres, sprite thickness
  Layer layer(int bone) const { return layers_[bone]; }
  const BoneLocal& rest(int bone) const { return rest_[bone]; }

  const std::vector<int>& parents() const { return parents_; }
  const std::vector<BoneLocal>& rest_locals() const { return rest_; }

  // Index of the bone named `name`, or -1.
  int find(std::string_view name) const;
  // Number of bones with the given kind.
  int count(BoneKind kind) const;

  // Changes a bone's rest transform (used while building, e.g. after leg placement).
  void set_rest(int bone, const BoneLocal& rest) { rest_[bone] = rest; }

  // Sprite orientation: a bone whose anatomical dorsal/front side lies on its local -y
  // (e.g. vertebrae behind the root, whose bones point tail-wards so local +y is ventral)
  // is drawn mirrored across its own axis.
  bool sprite_flip_y(int bone) const { return flip_y_[bone] != 0; }
  void set_sprite_flip_y(int bone, bool flip) { flip_y_[bone] = flip ? 1 : 0; }

  // True when every parent precedes its child and every value is finite and non-negative
  // where it must be.
  bool is_valid() const;

 private:
  std::vector<int> parents_;
  std::vector<std::string> names_;
  std::vector<BoneKind> kinds_;
  std::vector<float> lengths_;
  std::vector<float> widths_;
  std::vector<Layer> layers_;
  std::vector<BoneLocal> rest_;
  std::vector<uint8_t> flip_y_;
};

}  // namespace ossa
