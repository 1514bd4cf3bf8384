#pragma once
// CameraFollow — where the game's camera looks (DESIGN.md §8): the player's creature with
// its ground in the lower part of the view, ahead in the direction of motion, and down where
// it is going to land.
//
// Rules (hh = the view's half height, metres):
//   * ground framing: the creature's feet 0.55 hh below the view's centre;
//   * look ahead: the centre leads the creature by 0.8 s of its speed, at most 0.35 of the
//     half width, eased in over about a second;
//   * look down: the lowest ground within reach ahead (max(2.5 hip heights, 1.2 s of the
//     speed), in the direction of motion, once it moves a quarter hip height a second) and, in
//     the air, the ground under the creature are the "landing": when it lies more than 0.6 hip
//     heights below the feet (distances in the creature's size: a 3 cm frog and a 3 m
//     dinosaur see their drops alike), the centre goes down until the landing is
//     0.2 hh above the bottom edge — but never so far that the creature's top (half a hip
//     height over the root) leaves the top 15 % of the view; when both do not fit, the view
//     zooms out (up to 1.6 times its height; quickly out, slowly back in). Going down eases
//     twice as fast as going up, so a 4 m drop's landing is on screen well before the feet
//     touch (tests/app: every ledge of levels/drops.json, at least 0.3 s);
//   * the creature never leaves the inner 80 % of the width.
// The centre eases towards these targets exponentially (no overshoot): at rest, with the
// targets still, the camera stands still.

#include <optional>

#include <glm/vec2.hpp>

namespace ossa {

class Level;

// Half the view's height (metres) that frames a creature of hip height h and body length L
// in a view `aspect` times as wide as high: room for the body and the ground around it. Below
// h = 0.3 m it shrinks with the creature (5 h), so a 3 cm frog at its true size fills a good
// part of the picture instead of a few pixels; a long body (a 27 m whale) has its length
// within two thirds of the width.
float framing_half_height(float hip_height, float length, float aspect);

struct CameraSubject {
  glm::vec2 root_ws{0.0f};   // the creature's root (interpolated for the frame)
  float hip_height = 1.0f;   // metres: the feet are this far below the root
  float velocity_x = 0.0f;   // m/s
  bool airborne = false;
};

class CameraFollow {
 public:
  // Jumps to the framing of `s` (no easing): a new level or creature.
  void reset(const Level& level, const CameraSubject& s, float half_height, float aspect);
  // Eases towards the framing of `s` over dt seconds; returns the centre.
  glm::vec2 update(const Level& level, const CameraSubject& s, float half_height, float aspect, float dt);
  glm::vec2 center_ws() const { return center_ws_; }
  // The view's half height for a base half height (zoomed out while a landing and the
  // creature would not both fit).
  float half_height(float base) const { return base * zoom_; }
  // The ground the camera looks down to (nullopt: none more than 0.6 hip heights below the feet).
  std::optional<float> landing_y() const { return landing_y_; }

 private:
  glm::vec2 target(const Level& level, const CameraSubject& s, float half_height);
  glm::vec2 center_ws_{0.0f};
  float look_ahead_ = 0.0f;  // metres, eased
  float zoom_ = 1.0f, want_zoom_ = 1.0f;  // >= 1: zoomed out
  std::optional<float> landing_y_;
};

}  // namespace ossa
