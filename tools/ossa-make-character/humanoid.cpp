// The shipped humanoid (assets/characters/humanoid.*): a person in side view, facing +x, feet
// on y = 0, metres. "_l" is the near side (in front of the body, z > 0), "_r" the far side
// (behind, z < 0, drawn darker). Both hips are one joint, as in any side view: the far leg
// is turned back about it by a few degrees (its foot level) and the far arm hangs a little
// ahead, so that both sides show in the rest pose.

#include <algorithm>

#include "character_def.h"

namespace make_character {

namespace {

const Rgb kSkin = rgb(241, 194, 155), kShirt = rgb(212, 74, 62), kPants = rgb(60, 92, 158),
          kBelt = rgb(82, 54, 36), kShoe = rgb(74, 58, 50), kSole = rgb(44, 36, 34),
          kHair = rgb(112, 68, 38), kMouth = rgb(150, 60, 60);

const vec2 kHip{0.0f, 0.95f};
const float kAnkleY = 0.08f;
const float kFarArmDx = 0.035f;   // the far arm hangs this far ahead
const float kFarFootDx = -0.05f;  // the far foot stands this far behind
const float kToe = 0.19f;         // the shoe's toe, ahead of the ankle (its ground contact)

// The far leg turned about the hip so that its ankle lands kFarFootDx behind.
Mat2x3 far_leg_place() { return rotation_about(kHip, -std::asin(-kFarFootDx / (kHip.y - kAnkleY))); }
// The far foot: moved (not turned) to the far leg's ankle, so its sole stays level.
Mat2x3 far_foot_place() { return translation(far_leg_place().apply({0.0f, kAnkleY}) - vec2(0.0f, kAnkleY)); }

}  // namespace

CharacterDef humanoid() {
  CharacterDef def;
  def.name = "humanoid";
  const float up = kPi / 2, down = -kPi / 2;
  def.bones = {
      {"pelvis", "", kHip, up},
      {"spine", "pelvis", {0.0f, 1.07f}, up},
      {"chest", "spine", {0.0f, 1.27f}, up},
      {"neck", "chest", {0.01f, 1.47f}, up},
      {"head", "neck", {0.01f, 1.55f}, up},
  };
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const Mat2x3 arm = side == 0 ? Mat2x3{} : translation({kFarArmDx, 0.0f});
    const Mat2x3 leg = side == 0 ? Mat2x3{} : far_leg_place();
    const Mat2x3 foot = side == 0 ? Mat2x3{} : far_foot_place();
    def.bones.push_back(placed({"upper_arm" + s, "chest", {0.0f, 1.42f}, down}, arm));
    def.bones.push_back(placed({"lower_arm" + s, "upper_arm" + s, {0.0f, 1.15f}, down}, arm));
    def.bones.push_back(placed({"hand" + s, "lower_arm" + s, {0.0f, 0.90f}, down}, arm));
    def.bones.push_back(placed({"thigh" + s, "pelvis", kHip, down}, leg));
    def.bones.push_back(placed({"shin" + s, "thigh" + s, {0.0f, 0.50f}, down}, leg));
    def.bones.push_back(placed({"foot" + s, "shin" + s, {0.0f, kAnkleY}, 0.0f}, foot));
  }

  const float ow = 0.012f;  // detail line width
  // Torso: pelvis, spine, chest and neck in one strip.
  {
    Part p("torso", 0.0f, {-0.17f, 0.84f}, {0.17f, 1.58f}, false);
    p.rows = {{1.58f, W{{"neck", 0.5f}, {"head", 0.5f}}}, {1.47f, W{{"chest", 0.6f}, {"neck", 0.4f}}},
              {1.37f, W{{"chest", 1}}}, {1.27f, W{{"spine", 0.5f}, {"chest", 0.5f}}},
              {1.17f, W{{"spine", 1}}}, {1.07f, W{{"pelvis", 0.5f}, {"spine", 0.5f}}},
              {0.95f, W{{"pelvis", 1}}}, {0.84f, W{{"pelvis", 1}}}};
    p.layers = {
        {capsule({0.0f, 1.42f}, {0.015f, 1.57f}, 0.05f, 0.045f), kSkin},
        {rounded_box({-0.12f, 0.86f}, {0.12f, 1.04f}, 0.05f), kPants},
        {[](vec2 q) {  // shirt: a rounded torso, a little fuller at the chest
           const float box = rounded_box({-0.125f, 1.0f}, {0.12f, 1.46f}, 0.07f)(q);
           return std::min(box, ellipse({0.03f, 1.33f}, 0.11f, 0.11f)(q));
         },
         kShirt, ow},
        {rounded_box({-0.125f, 0.985f}, {0.125f, 1.03f}, 0.008f), kBelt, 0.008f},
        {rounded_box({0.05f, 0.992f}, {0.09f, 1.023f}, 0.005f), rgb(214, 178, 90), 0.006f, false},
    };
    def.parts.push_back(p);
  }
  // Head.
  {
    Part p("head", 0.05f, {-0.15f, 1.50f}, {0.18f, 1.86f}, false);
    p.rows = {{1.86f, W{{"head", 1}}}, {1.50f, W{{"head", 1}}}};
    p.layers = {
        {ellipse({0.015f, 1.675f}, 0.115f, 0.13f), kSkin},
        {circle({0.125f, 1.66f}, 0.026f), kSkin},                                   // nose
        {clip(ellipse({-0.005f, 1.715f}, 0.128f, 0.105f), {0.0f, 1.705f}, {0.45f, -1.0f}), kHair, ow},
        {circle({-0.015f, 1.65f}, 0.026f), kSkin, 0.01f, false},                    // ear
        {ellipse({0.072f, 1.69f}, 0.014f, 0.02f), kOutline, 0.0f, false},            // eye
        {circle({0.076f, 1.697f}, 0.005f), kWhite, 0.0f, false},
        {capsule({0.05f, 1.725f}, {0.095f, 1.73f}, 0.006f, 0.006f), kHair, 0.0f, false},  // brow
        {capsule({0.075f, 1.6f}, {0.105f, 1.607f}, 0.006f, 0.006f), kMouth, 0.0f, false},
    };
    def.parts.push_back(p);
  }
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const bool far = side == 1;
    const float sign = far ? -1.0f : 1.0f;
    // Leg: thigh and shin in one strip, blended at the hip and the knee.
    {
      Part p("leg" + s, 0.1f * sign, {-0.105f, 0.04f}, {0.105f, 1.03f}, false);
      p.far = far;
      p.place = far ? far_leg_place() : Mat2x3{};
      p.rows = {{1.03f, W{{"pelvis", 0.5f}, {"thigh" + s, 0.5f}}},
                {0.93f, W{{"pelvis", 0.2f}, {"thigh" + s, 0.8f}}},
                {0.75f, W{{"thigh" + s, 1}}},
                {0.58f, W{{"thigh" + s, 0.85f}, {"shin" + s, 0.15f}}},
                {0.50f, W{{"thigh" + s, 0.5f}, {"shin" + s, 0.5f}}},
                {0.42f, W{{"thigh" + s, 0.15f}, {"shin" + s, 0.85f}}},
                {0.25f, W{{"shin" + s, 1}}},
                {0.10f, W{{"shin" + s, 0.9f}, {"foot" + s, 0.1f}}},
                {0.04f, W{{"shin" + s, 0.8f}, {"foot" + s, 0.2f}}}};
      p.layers = {
          {capsule({0.0f, 0.5f}, {0.0f, 0.1f}, 0.068f, 0.055f), kPants},
          {capsule({0.0f, 0.94f}, {0.0f, 0.5f}, 0.092f, 0.07f), kPants},
          {rounded_box({-0.06f, 0.06f}, {0.06f, 0.13f}, 0.01f), kPants},  // cuff
      };
      def.parts.push_back(p);
    }
    // Foot (shoe), rows along x.
    {
      Part p("foot" + s, 0.12f * sign, {-0.08f, -0.005f}, {0.22f, 0.13f}, true);
      p.far = far;
      p.place = far ? far_foot_place() : Mat2x3{};
      p.rows = {{-0.08f, W{{"foot" + s, 0.8f}, {"shin" + s, 0.2f}}},
                {0.06f, W{{"foot" + s, 1}}},
                {0.22f, W{{"foot" + s, 1}}}};
      p.layers = {
          {[=](vec2 q) {
             return std::min(capsule({-0.01f, 0.055f}, {0.15f, 0.045f}, 0.05f, 0.04f)(q),
                             rounded_box({-0.055f, 0.04f}, {0.045f, 0.115f}, 0.02f)(q));
           },
           kShoe},
          {rounded_box({-0.065f, 0.0f}, {0.195f, 0.022f}, 0.01f), kSole, 0.006f},
          {capsule({0.02f, 0.09f}, {0.07f, 0.07f}, 0.005f, 0.005f), rgb(220, 210, 190), 0.0f, false},  // lace
      };
      def.parts.push_back(p);
    }
    // Arm: upper arm (short sleeve) and forearm, blended at the shoulder and the elbow.
    {
      Part p("arm" + s, 0.2f * sign, {-0.075f, 0.86f}, {0.075f, 1.50f}, false);
      p.far = far;
      p.place = far ? translation({kFarArmDx, 0.0f}) : Mat2x3{};
      p.rows = {{1.50f, W{{"chest", 0.5f}, {"upper_arm" + s, 0.5f}}},
                {1.40f, W{{"chest", 0.15f}, {"upper_arm" + s, 0.85f}}},
                {1.28f, W{{"upper_arm" + s, 1}}},
                {1.21f, W{{"upper_arm" + s, 0.85f}, {"lower_arm" + s, 0.15f}}},
                {1.15f, W{{"upper_arm" + s, 0.5f}, {"lower_arm" + s, 0.5f}}},
                {1.09f, W{{"upper_arm" + s, 0.15f}, {"lower_arm" + s, 0.85f}}},
                {0.98f, W{{"lower_arm" + s, 1}}},
                {0.86f, W{{"lower_arm" + s, 0.8f}, {"hand" + s, 0.2f}}}};
      p.layers = {
          {capsule({0.0f, 1.15f}, {0.0f, 0.9f}, 0.045f, 0.038f), kSkin},
          {capsule({0.0f, 1.41f}, {0.0f, 1.15f}, 0.055f, 0.047f), kSkin},
          {clip(capsule({0.0f, 1.42f}, {0.0f, 1.2f}, 0.066f, 0.058f), {0.0f, 1.25f}, {0.0f, -1.0f}), kShirt, 0.012f},
      };
      def.parts.push_back(p);
    }
    // Hand.
    {
      Part p("hand" + s, 0.21f * sign, {-0.06f, 0.76f}, {0.07f, 0.94f}, false);
      p.far = far;
      p.place = far ? translation({kFarArmDx, 0.0f}) : Mat2x3{};
      p.rows = {{0.94f, W{{"hand" + s, 0.7f}, {"lower_arm" + s, 0.3f}}}, {0.76f, W{{"hand" + s, 1}}}};
      p.layers = {
          {capsule({0.0f, 0.905f}, {0.005f, 0.83f}, 0.042f, 0.045f), kSkin},
          {capsule({0.03f, 0.87f}, {0.045f, 0.83f}, 0.016f, 0.014f), kSkin, 0.008f, false},
      };
      def.parts.push_back(p);
    }
  }

  // The rig mapping: each foot touches the ground at its toe.
  def.rig = {{"root", "pelvis"}, {"spine", {"spine", "chest"}}, {"neck", {"neck"}}, {"head", "head"}};
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const vec2 toe = (side == 0 ? Mat2x3{} : far_foot_place()).apply({kToe, 0.0f});
    def.rig["legs"].push_back({{"side", side == 0 ? "near" : "far"}, {"upper", "thigh" + s}, {"lower", "shin" + s},
                               {"foot", "foot" + s}, {"contact", {ossa::json_float(toe.x), ossa::json_float(toe.y)}}});
    def.rig["arms"].push_back({{"side", side == 0 ? "near" : "far"}, {"upper", "upper_arm" + s},
                               {"lower", "lower_arm" + s}, {"hand", "hand" + s}});
  }
  return def;
}

}  // namespace make_character
