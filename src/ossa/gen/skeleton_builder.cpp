#include "ossa/gen/skeleton_builder.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

#include "ossa/gen/body_plan.h"
#include "ossa/gen/true_size.h"
#include "ossa/math/angle.h"

namespace ossa {

namespace {

// Non-terminals of the skeleton grammar [Z 5.2]. Each has exactly one rule; a rule emits
// bones (terminals) whose parents already exist and pushes further non-terminals, so the
// flat skeleton comes out parents-first by construction.
enum class Symbol { kSkeleton, kSpine, kBackFront, kBackRear, kNeck, kTail, kSkull, kRibs, kGirdle, kLimb };

struct Item {
  Symbol symbol;
  int a = 0;  // girdle kind / limb gene index / rib range start
  int b = 0;  // slot / side
};

class Assembler {
 public:
  Assembler(const Genome& g, const BodyPlan& plan) : g_(g), plan_(plan) {
    c_.scale = g.scale;
    c_.origin_frame = {plan.joints[plan.root_joint].x, plan.ground_y};
    c_.name = g.name;
    c_.contact = g.contact;
    c_.skull_variant = g.skull_variant;
    c_.smooth_skinning = g.options.smooth_skinning;
    c_.gait_family = g.gait_family;
    c_.skull_snout = g.skull_shape.snout;
    c_.look = g.look;
    c_.appendages = g.appendages;
    c_.weight_kg = static_cast<float>(g.pca[kWeightKg]);
    bone_ending_at_.assign(plan.joints.size(), -1);
  }

  Result<Creature> run() {
    std::deque<Item> queue{{Symbol::kSkeleton}};
    while (!queue.empty()) {
      const Item item = queue.front();
      queue.pop_front();
      if (Status s = apply(item, queue); !s.ok()) return s.error();
    }
    c_.skeleton = std::move(sk_);
    c_.rest_pose = Pose::rest(c_.skeleton);
    if (!c_.skeleton.is_valid()) {
      return Error::at("", "genome", "builds a skeleton with non-finite values");
    }
    return std::move(c_);
  }

 private:
  // --- bone emission -------------------------------------------------------------------
  glm::vec2 ms(glm::vec2 fu) const { return c_.frame_to_model(fu); }

  // Adds a bone from `start_fu` at absolute frame angle `angle`, `length_fu` long.
  int emit(std::string name, BoneKind kind, int parent, glm::vec2 start_fu, float angle,
           float length_fu, float width_fu, Layer layer) {
    BoneLocal local;
    const glm::vec2 start = ms(start_fu);
    if (parent < 0) {
      local.offset_ls = start;
      local.angle_ls = angle;
    } else {
      const float pa = abs_angle_[parent];
      const glm::vec2 d = start - start_ms_[parent];
      const float c = std::cos(-pa), s = std::sin(-pa);
      local.offset_ls = {c * d.x - s * d.y, s * d.x + c * d.y};
      local.angle_ls = wrap_angle(angle - pa);
    }
    const int bone = sk_.add_bone(std::move(name), kind, parent, length_fu * g_.scale,
                                  width_fu * g_.scale, local, layer);
    abs_angle_.push_back(angle);
    start_ms_.push_back(start);
    return bone;
  }

  // A bone from joint `from` to joint `to` of the spine.
  int emit_segment(const std::string& name, BoneKind kind, int parent, int from, int to,
                   float width_fu) {
    const glm::vec2 a = plan_.joints[from], b = plan_.joints[to];
    const glm::vec2 d = b - a;
    const float length = std::sqrt(d.x * d.x + d.y * d.y);
    // A zero-length segment keeps its parent's direction.
    const float angle = length > 1e-6f ? std::atan2(d.y, d.x) : (parent >= 0 ? abs_angle_[parent] : 0.0f);
    const int bone = emit(name, kind, parent, a, angle, length, width_fu, Layer::kBody);
    bone_ending_at_[to] = bone;
    return bone;
  }

  float vertebra_width(int joint) const {
    const float s = plan_.body_size;
    const float f = plan_.back_fraction[joint];
    if (f < 0.0f) {  // neck: thinner toward the head
      const float u = static_cast<float>(joint) / std::max(1, plan_.shoulder_joint);
      return s * (0.035f + 0.02f * u);
    }
    if (f > 1.0f) {  // tail: tapers to the tip
      const int n = static_cast<int>(plan_.joints.size()) - 1 - plan_.hip_joint;
      const float u = static_cast<float>(joint - plan_.hip_joint) / std::max(1, n);
      return s * (0.05f - 0.038f * u);
    }
    return s * 0.06f;
  }

  // --- rules ---------------------------------------------------------------------------
  Status apply(const Item& item, std::deque<Item>& queue) {
    switch (item.symbol) {
      case Symbol::kSkeleton: {  // Skeleton → root + Spine
        c_.root = emit("root", BoneKind::kRoot, kNoParent, plan_.joints[plan_.root_joint], 0.0f,
                       0.0f, 0.0f, Layer::kBody);
        bone_ending_at_[plan_.root_joint] = c_.root;
        queue.push_back({Symbol::kSpine});
        return {};
      }
      case Symbol::kSpine:  // Spine → Back (front half) + Back (rear half)
        queue.push_back({Symbol::kBackFront});
        queue.push_back({Symbol::kBackRear});
        return {};
      case Symbol::kBackFront: {  // root → shoulder; then Neck, Ribs, shoulder Girdle
        int parent = c_.root;
        for (int j = plan_.root_joint; j > plan_.shoulder_joint; --j) {
          parent = emit_segment("back_f" + std::to_string(plan_.root_joint - j), BoneKind::kBackVertebra,
                                parent, j, j - 1, vertebra_width(j - 1));
          c_.back.insert(c_.back.begin(), parent);
        }
        queue.push_back({Symbol::kNeck});
        queue.push_back({Symbol::kRibs, 0});
        queue.push_back({Symbol::kGirdle, static_cast<int>(GirdleKind::kShoulder)});
        return {};
      }
      case Symbol::kBackRear: {  // root → hip; then Tail, Ribs, hip Girdle
        int parent = c_.root;
        for (int j = plan_.root_joint; j < plan_.hip_joint; ++j) {
          parent = emit_segment("back_r" + std::to_string(j - plan_.root_joint), BoneKind::kBackVertebra,
                                parent, j, j + 1, vertebra_width(j + 1));
          sk_.set_sprite_flip_y(parent, true);
          c_.back.push_back(parent);
        }
        queue.push_back({Symbol::kTail});
        queue.push_back({Symbol::kRibs, 1});
        queue.push_back({Symbol::kGirdle, static_cast<int>(GirdleKind::kHip)});
        return {};
      }
      case Symbol::kNeck: {  // shoulder → head end; then Skull, neck Girdle
        int parent = bone_ending_at_[plan_.shoulder_joint];
        for (int j = plan_.shoulder_joint; j > 0; --j) {
          parent = emit_segment("neck" + std::to_string(plan_.shoulder_joint - j), BoneKind::kNeckVertebra,
                                parent, j, j - 1, vertebra_width(j - 1));
          c_.neck.insert(c_.neck.begin(), parent);
        }
        queue.push_back({Symbol::kSkull});
        queue.push_back({Symbol::kGirdle, static_cast<int>(GirdleKind::kNeck)});
        return {};
      }
      case Symbol::kTail: {
        int parent = bone_ending_at_[plan_.hip_joint];
        const int last = static_cast<int>(plan_.joints.size()) - 1;
        for (int j = plan_.hip_joint; j < last; ++j) {
          parent = emit_segment("tail" + std::to_string(j - plan_.hip_joint), BoneKind::kTailVertebra,
                                parent, j, j + 1, vertebra_width(j + 1));
          sk_.set_sprite_flip_y(parent, true);
          c_.tail.push_back(parent);
        }
        return {};
      }
      case Symbol::kSkull: {
        // Length and height from the genome's skull shape (its variant's default for files
        // written before skulls had proportions), the angle by variant.
        static constexpr float kAngle[kSkullVariants] = {-0.35f, -0.15f, -0.2f, 0.0f};
        const int v = std::clamp(g_.skull_variant, 0, kSkullVariants - 1);
        const float length = g_.skull_shape.length * plan_.body_size;
        c_.skull = emit("skull", BoneKind::kSkull, bone_ending_at_[0], plan_.joints[0], kAngle[v],
                        length, g_.skull_shape.height * length, Layer::kBody);
        return {};
      }
      case Symbol::kRibs: {  // Ribs on back vertebrae within [0, rib_interval] of the back
        const bool front_half = item.a == 0;
        const float depth = std::max(0.5f * (plan_.joints[plan_.shoulder_joint].y - plan_.ground_y),
                                     0.1f * plan_.body_size);
        for (int j = plan_.shoulder_joint; j <= plan_.hip_joint; ++j) {
          const float f = plan_.back_fraction[j];
          if ((j <= plan_.root_joint) != front_half || f > g_.rib_interval || j == plan_.root_joint) continue;
          const int vertebra = bone_ending_at_[j];
          // Longest near the front of the chest, shorter toward the end of the interval.
          const float u = g_.rib_interval > 0.0f ? f / g_.rib_interval : 0.0f;
          const float length = std::min(depth * (1.0f - 0.45f * u * u), 0.45f * plan_.body_size);
          const float angle = -0.5f * kPi - 0.35f - 0.25f * u;
          for (Layer layer : {Layer::kFar, Layer::kNear}) {
            const int rib = emit(std::string("rib_") + layer_name(layer) + std::to_string(j - plan_.shoulder_joint),
                                 BoneKind::kRib, vertebra, plan_.joints[j], angle, length,
                                 0.022f * plan_.body_size, layer);
            (void)rib;
          }
        }
        return {};
      }
      case Symbol::kGirdle: {  // Girdle → girdle bones + Limbs, for each slot in use
        const GirdleKind kind = static_cast<GirdleKind>(item.a);
        const GirdlePlan& gp = plan_.girdles[item.a];
        for (size_t i = 0; i < g_.limbs.size(); ++i) {
          const LimbGene& gene = g_.limbs[i];
          if (gene.girdle != kind) continue;
          if (!gp.exists || gene.slot < 0 || gene.slot >= kSlotsPerGirdle || gp.spine_joint[gene.slot] < 0) {
            return Error::at("", "limbs[" + std::to_string(i) + "]",
                             std::string("needs a ") + girdle_kind_name(kind) + " girdle slot " +
                                 std::to_string(gene.slot) + " that this body does not have");
          }
          if (!limb_allowed(gene.kind, kind)) {
            return Error::at("", "limbs[" + std::to_string(i) + "]",
                             std::string("a ") + limb_kind_name(gene.kind) + " is not allowed on the " +
                                 girdle_kind_name(kind) + " girdle");
          }
          queue.push_back({Symbol::kLimb, static_cast<int>(i), static_cast<int>(Side::kNear)});
          queue.push_back({Symbol::kLimb, static_cast<int>(i), static_cast<int>(Side::kFar)});
        }
        return {};
      }
      case Symbol::kLimb: {  // Limb → girdle bone (once per slot and side) + upper, lower, hand
        const LimbGene& gene = g_.limbs[item.a];
        const Side side = static_cast<Side>(item.b);
        const Layer layer = side == Side::kNear ? Layer::kNear : Layer::kFar;
        const int gk = static_cast<int>(gene.girdle);
        const GirdlePlan& gp = plan_.girdles[gk];
        const std::string suffix = std::string("_") + girdle_kind_name(gene.girdle) +
                                   std::to_string(gene.slot) + "_" + layer_name(layer);
        const auto key = std::make_tuple(gk, gene.slot, item.b);
        int girdle_bone;
        if (auto it = girdle_bones_.find(key); it != girdle_bones_.end()) {
          girdle_bone = it->second;
        } else {
          const glm::vec2 start = gp.girdle_start_fu[gene.slot];
          const glm::vec2 d = gp.joint_fu[gene.slot] - start;
          const float length = std::sqrt(d.x * d.x + d.y * d.y);
          const bool hip = gene.girdle == GirdleKind::kHip;
          girdle_bone = emit((hip ? "pelvis" : "scapula") + suffix, hip ? BoneKind::kPelvis : BoneKind::kScapula,
                             bone_ending_at_[gp.spine_joint[gene.slot]], start, std::atan2(d.y, d.x), length,
                             (hip ? 0.55f : 0.4f) * length, layer);
          girdle_bones_[key] = girdle_bone;
          if (hip) {
            if (c_.hip < 0) c_.hip = girdle_bone;
          } else if (gene.girdle == GirdleKind::kShoulder) {
            if (c_.shoulder < 0) c_.shoulder = girdle_bone;
          } else if (c_.neck_girdle < 0) {
            c_.neck_girdle = girdle_bone;
          }
        }
        const LimbLengths l = limb_lengths(plan_, g_, gene.kind, gene.girdle);
        const float len[3] = {static_cast<float>(l.upper), static_cast<float>(l.lower),
                              static_cast<float>(l.distal)};
        static constexpr BoneKind kKinds[3] = {BoneKind::kUpperLimb, BoneKind::kLowerLimb, BoneKind::kHand};
        static constexpr const char* kNames[3] = {"upper", "lower", "hand"};
        Limb limb;
        limb.kind = gene.kind;
        limb.girdle = gene.girdle;
        limb.slot = gene.slot;
        limb.side = side;
        limb.pair = item.a;
        limb.girdle_bone = girdle_bone;
        limb.front = gene.girdle != GirdleKind::kHip;
        limb.bend_sign = limb_bend_sign(gene.girdle);
        glm::vec2 p = gp.joint_fu[gene.slot];
        float angle = 0.0f;
        int parent = girdle_bone;
        for (int k = 0; k < 3; ++k) {
          angle = k == 0 ? gene.angles[0] : angle + gene.angles[k];
          const float width = std::clamp(0.11f * len[k], 0.012f * plan_.body_size, 0.05f * plan_.body_size);
          parent = emit(std::string(limb_kind_name(gene.kind)) + "_" + kNames[k] + suffix, kKinds[k], parent, p,
                        angle, len[k], width, layer);
          limb.bones[k] = parent;
          p += len[k] * glm::vec2(std::cos(angle), std::sin(angle));
        }
        c_.limbs.push_back(limb);
        return {};
      }
    }
    return {};
  }

  const Genome& g_;
  const BodyPlan& plan_;
  Creature c_;
  Skeleton sk_;
  std::vector<float> abs_angle_;      // per bone, frame = model space angle
  std::vector<glm::vec2> start_ms_;   // per bone
  std::vector<int> bone_ending_at_;   // per spine joint
  std::map<std::tuple<int, int, int>, int> girdle_bones_;
};

}  // namespace

Result<Creature> build_creature(const Genome& genome) {
  for (double v : genome.pca) {
    if (!std::isfinite(v)) return Error::at("", "pca", "expected finite values");
  }
  if (!(genome.scale > 0.0f) || !std::isfinite(genome.scale)) {
    return Error::at("", "scale", "expected a number > 0");
  }
  const BodyPlan plan = plan_body(genome);
  Result<Creature> creature = Assembler(genome, plan).run();
  if (creature) creature->body_mass_kg = expected_body_mass_kg(*creature, genome);
  return creature;
}

}  // namespace ossa
