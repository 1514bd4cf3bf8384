// The shipped dog (assets/characters/dog.*): a four-legged character in the humanoid's style
// (flat fills, dark outlines, the far side darker), side view facing +x, paws on y = 0. Drawn
// below in metres at 0.55 m at the shoulder and exported 1.5 times that (a big dog, 0.8 m):
// at 0.55 m the 25 cm risers of levels/stairs.json's 40° flight are 58 % of its hip height,
// and the body placement's knee clamp lifts it off its hind feet while both front paws swing
// up the flight (a 3-15 cm slide; README, Known limits). Its rig proves the rig path on two leg pairs: hind
// legs (thigh, shin, hind paw from the hock) hang from the pelvis, the root; front legs
// (upper arm, forearm, front paw from the wrist) from the chest. Knees bend forward, elbows
// back. Each far leg shares its near twin's hip or shoulder joint, turned a few degrees
// (hind back, front forward) so that all four show in the rest pose.

#include <algorithm>

#include "character_def.h"

namespace make_character {

namespace {

const Rgb kFur = rgb(205, 148, 86), kFurLight = rgb(243, 224, 192), kEar = rgb(138, 86, 48),
          kNose = rgb(42, 32, 34), kCollar = rgb(212, 74, 62), kTag = rgb(232, 196, 92);

// Joints of the rest pose (model space).
const vec2 kPelvis{-0.26f, 0.50f}, kSpine{-0.06f, 0.52f}, kChest{0.14f, 0.52f}, kNeck{0.24f, 0.58f},
    kHead{0.34f, 0.70f}, kSnout{0.56f, 0.64f};
const vec2 kTail1{-0.34f, 0.55f}, kTail2{-0.43f, 0.61f}, kTail3{-0.51f, 0.68f}, kTailTip{-0.58f, 0.76f};
const vec2 kHip{-0.27f, 0.44f}, kKnee{-0.21f, 0.27f}, kHock{-0.31f, 0.13f}, kHindPaw{-0.28f, 0.035f};
const vec2 kShoulder{0.16f, 0.42f}, kElbow{0.10f, 0.27f}, kWrist{0.14f, 0.08f}, kFrontPaw{0.17f, 0.035f};
const float kHindToe = -0.232f, kFrontToe = 0.203f;  // x of the paws' contact points: the front end of their flat soles

float dir(vec2 a, vec2 b) { return std::atan2(b.y - a.y, b.x - a.x); }

Mat2x3 far_place(bool hind) { return hind ? rotation_about(kHip, -0.09f) : rotation_about(kShoulder, 0.09f); }

// Rump, back and chest. The neck's sprite draws the part of it inside its own rectangle again,
// under one outline with the neck, so the back's line runs on into the neck's (the neck cut
// off at its rectangle's edge left a vertical seam and a step in the outline).
Sdf body_shape() { return unite(capsule({-0.27f, 0.50f}, {0.14f, 0.47f}, 0.115f, 0.14f), circle({-0.29f, 0.52f}, 0.11f)); }
Sdf chest_patch() { return intersect(ellipse_turned({0.2f, 0.43f}, 0.07f, 0.13f, 0.35f), body_shape()); }

}  // namespace

CharacterDef dog() {
  CharacterDef def;
  def.name = "dog";
  def.scale = 1.5f;
  def.bones = {
      {"pelvis", "", kPelvis, dir(kPelvis, kSpine)},
      {"spine", "pelvis", kSpine, dir(kSpine, kChest)},
      {"chest", "spine", kChest, dir(kChest, kNeck)},
      {"neck", "chest", kNeck, dir(kNeck, kHead)},
      {"head", "neck", kHead, dir(kHead, kSnout)},
      {"tail_1", "pelvis", kTail1, dir(kTail1, kTail2)},
      {"tail_2", "tail_1", kTail2, dir(kTail2, kTail3)},
      {"tail_3", "tail_2", kTail3, dir(kTail3, kTailTip)},
  };
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const Mat2x3 hind = side == 0 ? Mat2x3{} : far_place(true);
    const Mat2x3 front = side == 0 ? Mat2x3{} : far_place(false);
    def.bones.push_back(placed({"thigh" + s, "pelvis", kHip, dir(kHip, kKnee)}, hind));
    def.bones.push_back(placed({"shin" + s, "thigh" + s, kKnee, dir(kKnee, kHock)}, hind));
    def.bones.push_back(placed({"hind_paw" + s, "shin" + s, kHock, dir(kHock, kHindPaw)}, hind));
    def.bones.push_back(placed({"upper_arm" + s, "chest", kShoulder, dir(kShoulder, kElbow)}, front));
    def.bones.push_back(placed({"forearm" + s, "upper_arm" + s, kElbow, dir(kElbow, kWrist)}, front));
    def.bones.push_back(placed({"front_paw" + s, "forearm" + s, kWrist, dir(kWrist, kFrontPaw)}, front));
  }

  const float ow = 0.01f;  // detail line width
  // Body: rump, back and chest in one strip along x.
  {
    Part p("body", 0.0f, {-0.42f, 0.28f}, {0.32f, 0.68f}, true);
    p.rows = {{-0.42f, W{{"pelvis", 1}}}, {-0.26f, W{{"pelvis", 1}}}, {-0.16f, W{{"pelvis", 0.5f}, {"spine", 0.5f}}},
              {-0.06f, W{{"spine", 1}}}, {0.04f, W{{"spine", 0.5f}, {"chest", 0.5f}}}, {0.14f, W{{"chest", 1}}},
              {0.32f, W{{"chest", 1}}}};
    const Sdf body = body_shape();
    p.layers = {
        {body, kFur},
        {chest_patch(), kFurLight, 0.0f, false},  // chest
        {intersect(ellipse({-0.02f, 0.33f}, 0.2f, 0.045f), body), kFurLight, 0.0f, false},              // belly
    };
    def.parts.push_back(p);
  }
  // Tail: three bones, rows along x, curving up and back.
  {
    Part p("tail", -0.02f, {-0.62f, 0.46f}, {-0.28f, 0.82f}, true);
    p.rows = {{-0.62f, W{{"tail_3", 1}}}, {-0.51f, W{{"tail_2", 0.5f}, {"tail_3", 0.5f}}},
              {-0.43f, W{{"tail_1", 0.5f}, {"tail_2", 0.5f}}}, {-0.36f, W{{"pelvis", 0.4f}, {"tail_1", 0.6f}}},
              {-0.28f, W{{"pelvis", 1}}}};
    p.layers = {
        {unite(unite(capsule(kTail1 + vec2(0.04f, -0.01f), kTail2, 0.04f, 0.034f), capsule(kTail2, kTail3, 0.034f, 0.028f)),
               capsule(kTail3, kTailTip, 0.028f, 0.02f)),
         kFur},
        {clip(capsule(kTail3, kTailTip, 0.028f, 0.02f), kTail3 + vec2(-0.04f, 0.045f), {1.0f, -0.6f}), kFurLight, 0.0f, false},
    };
    def.parts.push_back(p);
  }
  // Neck, with the collar: chest to head, rows along x.
  {
    Part p("neck", 0.02f, {0.12f, 0.44f}, {0.40f, 0.80f}, true);
    p.rows = {{0.12f, W{{"chest", 1}}}, {0.20f, W{{"chest", 0.7f}, {"neck", 0.3f}}}, {0.26f, W{{"neck", 1}}},
              {0.32f, W{{"neck", 0.5f}, {"head", 0.5f}}}, {0.40f, W{{"head", 1}}}};
    const vec2 n = glm::normalize(kHead - kNeck), across(-n.y, n.x), c = kNeck + 0.3f * (kHead - kNeck);
    p.layers = {
        {unite(capsule(kChest + vec2(0.02f, -0.02f), kHead, 0.09f, 0.07f), body_shape()), kFur},
        {chest_patch(), kFurLight, 0.0f, false},
        {capsule(c + 0.08f * across, c - 0.085f * across, 0.018f, 0.018f), kCollar, 0.008f},
        {circle(c - 0.095f * across + vec2(0.0f, -0.012f), 0.018f), kTag, 0.008f, false},
    };
    def.parts.push_back(p);
  }
  // Head: skull, snout, ear, eye, nose.
  {
    Part p("head", 0.05f, {0.24f, 0.56f}, {0.62f, 0.90f}, false);
    p.rows = {{0.90f, W{{"head", 1}}}, {0.56f, W{{"head", 1}}}};
    p.layers = {
        {unite(ellipse({0.37f, 0.75f}, 0.095f, 0.08f), capsule({0.41f, 0.71f}, {0.545f, 0.675f}, 0.048f, 0.036f)), kFur},
        {clip(capsule({0.43f, 0.695f}, {0.545f, 0.67f}, 0.03f, 0.03f), {0.45f, 0.69f}, {0.2f, 1.0f}), kFurLight, 0.0f, false},
        {ellipse_turned({0.325f, 0.735f}, 0.032f, 0.075f, 0.45f), kEar, 0.009f},  // a floppy ear
        {ellipse({0.43f, 0.775f}, 0.013f, 0.017f), kOutline, 0.0f, false},         // eye
        {circle({0.434f, 0.781f}, 0.005f), kWhite, 0.0f, false},
        {ellipse({0.568f, 0.688f}, 0.022f, 0.018f), kNose, 0.0f},
        {capsule({0.49f, 0.652f}, {0.535f, 0.648f}, 0.005f, 0.005f), kOutline, 0.0f, false},  // mouth
    };
    def.parts.push_back(p);
  }
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const bool far = side == 1;
    const float sign = far ? -1.0f : 1.0f;
    // Hind leg: haunch, shin, hock and paw in one strip down from the hip.
    {
      Part p("hind_leg" + s, 0.1f * sign, {-0.42f, -0.005f}, {-0.12f, 0.58f}, false);
      p.far = far;
      p.place = far ? far_place(true) : Mat2x3{};
      p.rows = {{0.58f, W{{"pelvis", 0.6f}, {"thigh" + s, 0.4f}}}, {0.47f, W{{"pelvis", 0.3f}, {"thigh" + s, 0.7f}}},
                {0.37f, W{{"thigh" + s, 1}}}, {0.30f, W{{"thigh" + s, 0.7f}, {"shin" + s, 0.3f}}},
                {0.26f, W{{"thigh" + s, 0.3f}, {"shin" + s, 0.7f}}}, {0.20f, W{{"shin" + s, 1}}},
                {0.15f, W{{"shin" + s, 0.6f}, {"hind_paw" + s, 0.4f}}}, {0.11f, W{{"shin" + s, 0.2f}, {"hind_paw" + s, 0.8f}}},
                {-0.005f, W{{"hind_paw" + s, 1}}}};
      p.layers = {
          {unite(unite(ellipse_turned({-0.255f, 0.40f}, 0.085f, 0.13f, 0.3f), capsule(kHip, kKnee, 0.07f, 0.05f)),
                 unite(capsule(kKnee, kHock, 0.045f, 0.03f), capsule(kHock, kHindPaw, 0.03f, 0.028f))),
           kFur, ow},
          {rounded_box({-0.318f, 0.0f}, {kHindToe + 0.014f, 0.055f}, 0.024f), kFur, ow},  // paw
          {capsule({-0.255f, 0.012f}, {-0.255f, 0.04f}, 0.003f, 0.003f), kOutline, 0.0f, false},  // toes
          {capsule({-0.238f, 0.012f}, {-0.238f, 0.036f}, 0.003f, 0.003f), kOutline, 0.0f, false},
      };
      def.parts.push_back(p);
    }
    // Front leg: upper arm, forearm, wrist and paw down from the shoulder.
    {
      Part p("front_leg" + s, 0.11f * sign, {0.02f, -0.005f}, {0.28f, 0.52f}, false);
      p.far = far;
      p.place = far ? far_place(false) : Mat2x3{};
      p.rows = {{0.52f, W{{"chest", 0.6f}, {"upper_arm" + s, 0.4f}}}, {0.43f, W{{"chest", 0.3f}, {"upper_arm" + s, 0.7f}}},
                {0.33f, W{{"upper_arm" + s, 1}}}, {0.29f, W{{"upper_arm" + s, 0.7f}, {"forearm" + s, 0.3f}}},
                {0.25f, W{{"upper_arm" + s, 0.3f}, {"forearm" + s, 0.7f}}}, {0.16f, W{{"forearm" + s, 1}}},
                {0.10f, W{{"forearm" + s, 0.6f}, {"front_paw" + s, 0.4f}}}, {0.06f, W{{"forearm" + s, 0.2f}, {"front_paw" + s, 0.8f}}},
                {-0.005f, W{{"front_paw" + s, 1}}}};
      p.layers = {
          {unite(unite(ellipse_turned({0.145f, 0.40f}, 0.06f, 0.1f, -0.35f), capsule(kShoulder, kElbow, 0.055f, 0.042f)),
                 unite(capsule(kElbow, kWrist, 0.036f, 0.028f), capsule(kWrist, kFrontPaw, 0.028f, 0.027f))),
           kFur, ow},
          {rounded_box({0.122f, 0.0f}, {kFrontToe + 0.013f, 0.052f}, 0.023f), kFur, ow},  // paw
          {capsule({0.172f, 0.012f}, {0.172f, 0.038f}, 0.003f, 0.003f), kOutline, 0.0f, false},  // toes
          {capsule({0.19f, 0.012f}, {0.19f, 0.035f}, 0.003f, 0.003f), kOutline, 0.0f, false},
      };
      def.parts.push_back(p);
    }
  }

  // The rig mapping: two leg pairs (hind first, as listed), the tail, the paws touching the
  // ground at their front bottom points.
  def.rig = {{"root", "pelvis"}, {"spine", {"spine", "chest"}}, {"neck", {"neck"}}, {"head", "head"},
             {"tail", {"tail_1", "tail_2", "tail_3"}}};
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const vec2 toe = (side == 0 ? Mat2x3{} : far_place(true)).apply({kHindToe, 0.0f});
    def.rig["legs"].push_back({{"side", side == 0 ? "near" : "far"}, {"upper", "thigh" + s}, {"lower", "shin" + s},
                               {"foot", "hind_paw" + s}, {"contact", {ossa::json_float(toe.x), ossa::json_float(toe.y)}}});
  }
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "_l" : "_r";
    const vec2 toe = (side == 0 ? Mat2x3{} : far_place(false)).apply({kFrontToe, 0.0f});
    def.rig["legs"].push_back({{"side", side == 0 ? "near" : "far"}, {"upper", "upper_arm" + s}, {"lower", "forearm" + s},
                               {"foot", "front_paw" + s}, {"contact", {ossa::json_float(toe.x), ossa::json_float(toe.y)}},
                               {"knee", "back"}});
  }
  return def;
}

}  // namespace make_character
