#pragma once
// Animator — procedural walking and running for any generated creature on a box level
// ([T 4.4] generalised to any number of limbs, DESIGN.md §7).
//
// Each fixed step (update):
//   1. turn: a command against the facing mirrors the creature in place; the feet keep their
//      world positions (leg pairs swap which feet they stand on), knees keep bending the
//      right way because all IK runs in model space, where the creature always faces +x;
//   2. gait clock: one phase φ advancing at f = v/λ (stride λ from Alexander's relation
//      λ ≈ 2.3·h·Fr^0.3 × step_distance_multiplier); each leg is in stance while its local
//      phase φ + offset is below the duty factor β; offsets follow the gait (biped
//      alternation, quadruped walk/trot/gallop by Froude number, metachronal waves for more
//      pairs); β falls from walk to run, below 0.5 giving a flight phase;
//   3. legs: at lift-off set_new_splines plans the swing — landing half a stance ahead of
//      where the girdle will be, ground looked up there, the blended walk/run prototype
//      mapped onto it and raised until the foot clears every box; stance feet stay fixed in
//      the world; a leg with no foothold ahead stops the creature at the edge;
//   4. body: each girdle's height = mean ground under its feet + its rest height + bob; the
//      spine pitches between girdles and leans into speed, clamped so no stance leg
//      over-extends; the head stays level, the tail swings with damped secondary motion;
//   5. pose: two-bone IK for every leg (a hoof or toe rolls about its contact point when the
//      leg would over-extend, so the whole limb reaches), arm swing counter to the same-side
//      leg, folded wings, trailing fins, a travelling wave for legless bodies. Limbs keep out
//      of the level: a swinging leg that meets a step lifts or tucks its foot, arms fold, fins
//      turn up; the body never folds a leg tighter than it bends nor lets a knee touch ground.
//
// Everything is deterministic: the same inputs give bit-identical poses.

#include <array>
#include <cmath>
#include <vector>

#include "ossa/anim/animator_params.h"
#include "ossa/anim/spline_prototypes.h"
#include "ossa/gen/creature.h"
#include "ossa/level/level.h"
#include "ossa/math/hermite.h"
#include "ossa/skeleton/pose.h"

namespace ossa {

enum class LegState : uint8_t { kStance, kSwing };
enum class Gait : uint8_t { kIdle, kWalk, kRun, kTrot, kGallop, kCrawl };
const char* gait_name(Gait gait);

class Animator {
 public:
  Animator(const Creature& creature, SplinePrototypes prototypes, AnimatorParams params = {});

  // Stands the creature on the ground below `position_ws` (x, and a height to search down
  // from), feet under their girdles, facing +x (facing = 1) or -x (-1).
  void reset(glm::vec2 position_ws, const Level& level, int facing = 1);

  // One fixed step of dt seconds towards `desired_velocity` (m/s, signed along x).
  void update(float dt, float desired_velocity, const Level& level);

  // ---- [T] tuning -------------------------------------------------------------------------
  const SplinePrototypes& spline_prototypes() const { return spline_prototypes_; }
  // New prototypes take effect at each leg's next lift-off (set_new_splines).
  void set_spline_prototypes(const SplinePrototypes& prototypes) { spline_prototypes_ = prototypes; }
  AnimatorParams& params() { return params_; }
  const AnimatorParams& params() const { return params_; }

  // ---- Output -----------------------------------------------------------------------------
  const Creature& creature() const { return *creature_; }
  // The joint values of the current pose (the legs' angles are worked out on first use after
  // an update: the matrices below do not need them).
  const Pose& pose() const;
  Mat2x3 model_to_world() const;
  // Model-space matrices of the current pose. update() computes the bones it needs (spine to
  // the girdles, limbs); the rest (ribs, neck, skull, tail...) on first use after an update,
  // so headless simulation and ticks between rendered frames do not pay for them.
  const std::vector<Mat2x3>& model_matrices() const;
  // World matrices of the current pose: model_to_world() · model, computed on first use after
  // an update (renderers that fold the placement into their palette never pay for it).
  const std::vector<Mat2x3>& world_matrices() const;

  // ---- State ------------------------------------------------------------------------------
  float x() const { return body_x_; }                 // world x of the root
  float velocity() const { return facing_ * speed_; } // m/s, signed
  int facing() const { return facing_; }
  Gait gait() const { return gait_; }
  float froude() const { return froude_; }
  float stride_length() const { return stride_; }     // metres per cycle
  float duty_factor() const { return duty_; }
  float cycle_frequency() const { return frequency_; } // cycles per second
  float run_factor() const { return run_factor_; }     // walk→run blend in [0, 1]
  bool blocked() const { return blocked_; }
  int steps() const { return steps_; }                 // touch-downs so far
  float hip_height() const { return hip_height_; }     // h of the Froude number, metres
  // Speeds at the walk and run reference Froude numbers (0.5 and 2.5), m/s.
  float walk_speed() const;
  float run_speed() const;

  int leg_count() const { return static_cast<int>(legs_.size()); }
  // [T] leg_state: stance or swing of leg i.
  LegState leg_state(int leg) const { return feet_[foot_of_leg_[leg]].state; }
  const Limb& leg_limb(int leg) const { return creature_->limbs[legs_[leg].limb]; }
  // Where leg i's contact point (tip, or heel for flat contact) is meant to be, world space.
  glm::vec2 foot_target_ws(int leg) const { return feet_[foot_of_leg_[leg]].pos_ws; }
  // The contact point the pose actually reaches (from the world matrices).
  glm::vec2 foot_ws(int leg) const;
  // Progress of leg i's swing in [0, 1] (0 while in stance).
  float swing_progress(int leg) const {
    const Foot& f = feet_[foot_of_leg_[leg]];
    return f.state == LegState::kSwing ? f.progress : 0.0f;
  }
  // True while the leg sets down after a stop (a short eased swing, not a step).
  bool easing(int leg) const { return feet_[foot_of_leg_[leg]].easing; }

 private:
  struct LegInfo {
    int limb = 0;
    int group = 0;
    float upper = 0.0f, lower = 0.0f;  // thigh and shin lengths, metres
    float reach = 0.0f;              // upper + lower, metres
    float fold = 0.0f;               // 1.02 |upper - lower|: the ankle stays this far from the joint
    float bend = 1.0f;               // the limb's bend sign
    float foot_length = 0.0f;
    glm::vec2 foot_offset_ms{0.0f};  // ankle → contact point in the rest pose (model space)
    float foot_angle_ms = 0.0f;      // rest absolute angle of the foot bone (model space)
    float girdle_rel_angle = NAN;    // girdle angle relative to the root (NaN: spine bends)
    glm::vec2 foot_dir_ms{1.0f, 0.0f};  // (cos, sin) of foot_angle_ms
    // Farthest the contact point gets from the girdle joint: the leg at kReachLimit and, for
    // tip contact, the foot pivoted into line with it.
    float contact_reach = 0.0f;
    float foot_span = 0.0f;          // |foot_offset_ms|: ankle to contact point
    float leg_reach = 0.0f;          // kReachLimit * reach
  };
  struct Group {                     // a girdle slot carrying a leg pair
    glm::vec2 joint_ms{0.0f};        // rest girdle joint, model space
    float rest_height = 0.0f;        // joint height above the rest ground, metres
    // What max_step_up is a fraction of: the rest height, or more for crouching legs that
    // reach further than they stand tall (max_step_down is a fraction of the rest height).
    float step_height = 0.0f;
    std::vector<int> legs;           // leg indices (near first)
  };
  // What a limb near a foot can meet: colliders whose tops are at most `base` (the ground the
  // foot stands or steps on) and, above that, none higher than `top`. A limb entirely above
  // both meets nothing, so the level need not be asked. The default knows nothing.
  struct Clearance {
    float base = -1e30f;
    float top = 1e30f;
    bool clear_above(float min_y) const { return min_y >= base - 0.5e-3f && min_y >= top + 1e-3f; }
  };
  struct Foot {                      // per foot: moves between legs when the creature turns
    LegState state = LegState::kStance;
    glm::vec2 pos_ws{0.0f};          // contact point target
    glm::vec2 from_ws{0.0f}, to_ws{0.0f};
    HermiteSpline swing_x, swing_y;  // blended prototypes of this swing (set_new_splines)
    float lift = 0.0f;               // metres per unit of swing_y
    float raise = 0.0f;              // extra clearance bump, metres
    float progress = 0.0f;           // swing progress s in [0, 1]
    float rate = 0.0f;               // ds per unit of phase (or per second when easing)
    bool easing = false;             // a stop: progress runs on time, not on phase
    float offset = 0.0f;             // phase offset (eases toward the owning leg's target)
    float phase_prev = 0.0f;
    float hover = 0.0f;              // seconds spent waiting above the landing point
    bool holds_body = false;         // standing behind and below, it held the body down
    Clearance stance_clear;          // around pos_ws while in stance
    Clearance stance_reach_clear;    // within a leg's reach of pos_ws while in stance
    Clearance swing_clear;           // around the path of the current swing
  };

  void set_new_splines(int leg, const Level& level, float swing_phase);  // [T] name: plans a swing
  // An eased, unlifted step of leg i to `to` (default: the nearest foothold ahead of the foot),
  // timed in seconds rather than phase: setting feet down after a stop, and corrections.
  void start_ease(int leg, const Level& level, const glm::vec2* to = nullptr);
  // start_ease to `spot`, already one sample into the step on this tick.
  void step_to(int leg, glm::vec2 spot, const Level& level);
  bool raise_for_clearance(int leg, const Level& level);
  static glm::vec2 swing_point(const Foot& f, float s);
  void reverse(const Level& level);
  void update_gait();
  float leg_target_offset(int leg) const;
  void update_target_offsets();  // leg_target_offset of every leg, when the gait blend moved
  bool find_landing(int leg, float x_wanted, const Level& level, glm::vec2* landing) const;
  // Does leg i's foot, standing at contact_ws as the creature now faces, clear every box?
  bool foot_fits(int leg, glm::vec2 contact_ws, const Level& level) const;
  // The nearest place to near_ws (either way along the ground) where leg i's foot fits;
  // prefer_reach: one the leg reaches from where its girdle is now, if there is one.
  bool nearest_fit(int leg, glm::vec2 near_ws, const Level& level, glm::vec2* spot, bool prefer_reach = false) const;
  bool nearest_fit_within(int leg, glm::vec2 near_ws, const Level& level, glm::vec2* spot, bool in_reach) const;
  // Does leg i reach p_ws (within kFootReach of its reach) from where its girdle is now?
  bool reaches(int leg, glm::vec2 p_ws) const;
  // Where leg i would land if it lifted now at `speed` (swing_phase < 0: a full swing).
  float landing_x(int leg, float speed, float swing_phase = -1.0f) const;
  // v rotated by the body angle pitch_ + lean_.
  glm::vec2 rotate_body(glm::vec2 v) const {
    const float angle = pitch_ + lean_;
    if (angle != body_angle_cached_) {
      body_angle_cached_ = angle;
      body_cs_ = {std::cos(angle), std::sin(angle)};
    }
    return {body_cs_.x * v.x - body_cs_.y * v.y, body_cs_.y * v.x + body_cs_.x * v.y};
  }
  // Would leg i's chain (joint, knee, ankle, toe), standing where it stands, cut into a box
  // with its girdle joint at joint_ms? (Callers skip it when nothing rises near the foot.)
  bool stance_leg_hits(int leg, glm::vec2 joint_ms, const Level& level) const;
  // How far the segment a-b (world) must rise to clear every box it cuts.
  float raise_to_clear(glm::vec2 a, glm::vec2 b, const Level& level) const;
  // Moves a girdle's joint up by dy, turning the body about the girdle at the other end.
  void move_girdle(int group, float dy);
  // Girdle joint of a leg group from the current body placement.
  glm::vec2 girdle_ws(int group) const {
    const glm::vec2 j = rotate_body(groups_[group].joint_ms - glm::vec2(0.0f, root_rest_y_));
    return to_world({j.x, j.y + root_y_});
  }
  // World boxes of the body's parts for the wall sweep: slabs of the spine, head, arms, fins
  // (slabs = true), or one box around them all.
  void body_boxes(bool slabs, std::vector<Box>* boxes) const;
  // A box holding body_boxes(false, ·)'s single box, from the root and the hull's extent (no
  // hull points), and *top_y the height of one of its points; false if fins or arms take part.
  bool body_bound_ws(Box* bound, float* top_y) const;
  void place_body(float dt, const Level& level);
  void build_pose(float dt, const Level& level);
  void keep_arm_above_ground(const Limb& arm, const Level& level);
  void keep_fin_clear(const Limb& fin, const Level& level);
  void keep_body_out(const Level& level);
  void keep_tail_clear(const Level& level);
  void body_fk();  // model matrices of the body: the root, the chains to the girdles, the girdles
  // Ankle of leg i for a contact point and girdle joint (model space) and the foot bone's
  // direction: the rest angle unless that over-extends the leg, else pivoted about the contact
  // (no further than the level allows, when one is given).
  // *limited: the level kept the foot from rolling as far as the leg's reach needs.
  glm::vec2 leg_ankle(int leg, glm::vec2 contact_ms, glm::vec2 joint_ms, const Level* level, const Clearance& near,
                      glm::vec2* foot_dir, bool* limited) const;
  // leg_ankle's rare part, out of line so that the common one stays small: turns a rolled
  // foot back until it clears the level; false if it already did.
  [[gnu::noinline]] bool limit_foot_roll(int leg, glm::vec2 contact_ms, const Level& level, glm::vec2* foot_dir) const;
  // The point the girdle joint of leg i must stay within *radius of: the contact point (foot
  // free to roll) or the ankle (foot held by the level).
  glm::vec2 leg_anchor(int leg, glm::vec2 contact_ms, glm::vec2 joint_ms, const Level& level, const Clearance& near,
                       float* radius) const;
  Clearance clearance_in(const Box& region, float base, const Level& level) const;
  void update_stance_clearance(Foot& f, const Level& level) const;
  void update_swing_clearance(int leg, const Level& level);
  glm::vec2 to_model(glm::vec2 p_ws) const { return {(p_ws.x - body_x_) * facing_, p_ws.y}; }
  glm::vec2 to_world(glm::vec2 p_ms) const { return {body_x_ + facing_ * p_ms.x, p_ms.y}; }

  const Creature* creature_;
  SplinePrototypes spline_prototypes_;
  AnimatorParams params_;

  std::vector<LegInfo> legs_;
  std::vector<Group> groups_;        // sorted front (largest x) to back
  std::vector<Foot> feet_;
  std::vector<int> foot_of_leg_;
  std::vector<int> arms_, fins_, wings_;  // limb indices
  // The same, one of each left/right pair whose rest poses coincide in the side view: the
  // rest-pose keep-outs of place_body test each outline once.
  std::vector<int> outline_arms_, outline_fins_, outline_wings_;
  float hip_height_ = 1.0f;
  float climb_height_ = 0.0f;        // the least step_height of any girdle: a step up more
                                     // than max_step_up of it is a wall (the others could not follow)
  float root_rest_y_ = 0.0f;         // model-space y of the root in the rest pose
  // One girdle only: the foremost arm or wing shoulder ahead of it (rest, relative to the
  // girdle joint), and how much higher the ground under it may be than under the girdle
  // before the body pitches up.
  glm::vec2 front_shoulder_{0.0f};
  float front_slack_ = 0.0f;
  float body_half_length_ = 0.5f;

  mutable Pose pose_;
  // Per leg: upper, lower and foot bone directions (model space) of the current pose.
  std::vector<std::array<glm::vec2, 3>> leg_dirs_;
  mutable bool leg_angles_dirty_ = false;
  std::vector<Mat2x3> model_rest_;
  mutable std::vector<Mat2x3> model_;
  mutable std::vector<Mat2x3> world_;
  mutable bool world_dirty_ = true;
  mutable bool model_dirty_ = true;       // bones outside tick_bone_ are stale
  // Per-tick forward kinematics touches few bones: the root, the girdles (rigid to the root:
  // one product each, skipping the vertebrae between) and the limb chains. The rest is
  // computed in model_matrices() on demand.
  std::vector<int> needed_bones_;         // chain-computed each tick, parents first
  std::vector<int> girdle_bones_;         // computed directly from the root each tick
  std::vector<Mat2x3> girdle_rel_;        // their rest matrices relative to the root bone
  std::vector<uint8_t> tick_bone_;        // bones update() keeps current
  std::vector<Mat2x3> rest_local_m_;      // rest local matrix per bone
  std::vector<uint8_t> dynamic_bone_;     // joint values the animator changes (spine, skull, tail)
  std::vector<int> touched_bones_;        // bones whose joint values build_pose rewrites
  std::vector<int> other_limb_bones_;     // limb bones not placed by the leg IK, parents first
  // Wall sweep: hulls of the root, back and neck in slabs along the body, relative to the root
  // bone's frame, and the skull (kept level) as its joint in that frame plus its rest span.
  // Empty when the spine bends.
  std::vector<std::vector<glm::vec2>> body_slabs_;
  std::vector<glm::vec2> body_hull_;      // all slabs together
  std::vector<Box> body_boxes_;           // scratch for the wall sweep
  mutable std::vector<int> segment_hits_; // scratch for leg_ankle
  glm::vec2 skull_rel_{0.0f}, skull_span_{0.0f};
  glm::vec2 body_lo_{0.0f}, body_hi_{0.0f};  // body_bound_ws: extent of the hull and skull joint
  glm::vec2 body_top_{0.0f};              // ... and the hull's highest point (root bone's frame)
  int tail_base_bone_ = -1;               // the tail's nearest ancestor kept current each tick
  std::vector<int> tail_between_;         // the bones from there to the tail (root first)...
  Mat2x3 tail_between_rest_;              // ...or, when none of them bends, their rest product
  float tail_length_ = 0.0f;              // > 0: keep_tail_clear runs
  std::vector<float> group_height_;       // scratch for place_body
  std::vector<float> group_need_, group_room_, group_swing_up_;  // scratch for place_body's clamps
  std::vector<float> target_offset_;      // per leg: leg_target_offset at offsets_trot_/gallop_
  float offsets_trot_ = -1.0f, offsets_gallop_ = -1.0f;
  std::vector<int> clearance_hits_;       // scratch for raise_for_clearance
  mutable float body_angle_cached_ = 0.0f;
  mutable glm::vec2 body_cs_{1.0f, 0.0f}; // cos, sin of body_angle_cached_
  float stride_froude_ = -1.0f, stride_pow_ = 0.0f;  // Fr^0.3 cache
  // The shortest horizontal reach of a stance leg at params_.stance_height (update_gait).
  float reach_x_stance_height_ = NAN, min_reach_x_ = 0.0f;
  struct Decay {                          // exp(-rate·dt) of each smoothed quantity, per (dt, ism)
    float dt = -1.0f, ism = -1.0f;
    float lean = 0.0f, run = 0.0f, gait = 0.0f, pitch = 0.0f, root = 0.0f;
  } decay_;

  // Body and gait state.
  float body_x_ = 0.0f;
  float root_y_ = 0.0f;              // world y of the root
  float pitch_ = 0.0f;               // model-space root rotation from terrain
  float pitch_target_ = 0.0f;        // the pitch of the ground under the girdles (place_body)
  float lean_ = 0.0f;
  int facing_ = 1;
  float speed_ = 0.0f;
  float phase_ = 0.0f;
  float frequency_ = 0.0f;
  float stride_ = 0.0f;
  float duty_ = 0.65f;
  float froude_ = 0.0f;
  float run_factor_ = 0.0f;
  float gallop_factor_ = 0.0f;
  float trot_factor_ = 0.0f;
  Gait gait_ = Gait::kIdle;
  bool moving_ = false;
  bool snap_body_ = false;
  bool blocked_ = false;
  int blocked_dir_ = 0;
  int blocked_leg_ = 0;
  float blocked_retry_ = 0.0f;
  float idle_time_ = 0.0f;
  float crawl_phase_ = 0.0f;
  float tail_angle_ = 0.0f, tail_rate_ = 0.0f;
  float root_vy_ = 0.0f;
  float body_lift_ = 0.0f;  // legless: how far keep_body_out has lately lifted the body
  int steps_ = 0;
};

}  // namespace ossa
