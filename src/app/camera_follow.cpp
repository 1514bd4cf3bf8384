#include "app/camera_follow.h"

#include <algorithm>
#include <cmath>

#include "ossa/level/level.h"

namespace ossa {

namespace {

constexpr float kFeetBelowCentre = 0.55f;  // of the half height
constexpr float kLandingAboveBottom = 0.2f;
constexpr float kRootBelowTop = 0.15f;
constexpr float kLookDownOfHip = 0.6f;     // hip heights below the feet before the camera looks down
constexpr float kMaxZoomOut = 1.6f;

}  // namespace

float framing_half_height(float hip_height, float length, float aspect) {
  const float by_height = std::min(std::clamp(1.8f * hip_height + 0.9f, 1.5f, 8.0f), 5.0f * hip_height);
  return std::max(by_height, 0.75f * length / std::max(aspect, 0.1f));
}

glm::vec2 CameraFollow::target(const Level& level, const CameraSubject& s, float hh) {
  const float feet = s.root_ws.y - s.hip_height;
  // The landing: the lowest ground ahead within reach, and in the air the ground below.
  std::optional<float> low;
  const auto consider = [&](std::optional<GroundHit> hit) {
    if (hit && hit->height_ws < feet - kLookDownOfHip * s.hip_height) low = low ? std::min(*low, hit->height_ws) : hit->height_ws;
  };
  const float reach_down = 3.0f * hh;
  if (std::abs(s.velocity_x) > 0.25f * s.hip_height) {
    const float dir = s.velocity_x > 0.0f ? 1.0f : -1.0f;
    const float reach = std::max(2.5f * s.hip_height, 1.2f * std::abs(s.velocity_x));
    for (int k = 1; k <= 8; ++k) {
      const float x = s.root_ws.x + dir * reach * static_cast<float>(k) / 8.0f;
      consider(level.ground_height_below(x - 0.05f, x + 0.05f, feet + 0.3f, reach_down));
    }
  }
  if (s.airborne) {
    const float x = s.root_ws.x + 0.5f * s.velocity_x;  // about where it comes down
    consider(level.ground_height_below(std::min(s.root_ws.x, x), std::max(s.root_ws.x, x), feet, reach_down));
  }
  landing_y_ = low;
  // Zoomed out as far as needed (at most kMaxZoomOut) for the landing and the creature's
  // top (half a hip height over its root) to fit between the margins.
  const float top = s.root_ws.y + 0.5f * s.hip_height;
  want_zoom_ = 1.0f;
  if (low) want_zoom_ = std::clamp((top - *low) / ((2.0f - kLandingAboveBottom - kRootBelowTop) * hh), 1.0f, kMaxZoomOut);
  const float h = hh * zoom_;
  float y = feet + kFeetBelowCentre * h;
  if (low) {
    y = std::min(y, *low + (1.0f - kLandingAboveBottom) * h);
    y = std::max(y, top - (1.0f - kRootBelowTop) * h);
  }
  return {s.root_ws.x + look_ahead_, y};
}

void CameraFollow::reset(const Level& level, const CameraSubject& s, float half_height, float aspect) {
  (void)aspect;
  look_ahead_ = 0.0f;
  zoom_ = 1.0f;
  center_ws_ = target(level, s, half_height);
}

glm::vec2 CameraFollow::update(const Level& level, const CameraSubject& s, float hh, float aspect, float dt) {
  // Look ahead in the walking direction: up to 0.35 of the half width, reached in ~1 s.
  const float max_ahead = 0.35f * hh * zoom_ * aspect;
  const float want_ahead = std::clamp(s.velocity_x * 0.8f, -max_ahead, max_ahead);
  look_ahead_ += (want_ahead - look_ahead_) * (1.0f - std::exp(-1.5f * dt));
  const glm::vec2 t = target(level, s, hh);
  // Out quickly (the landing comes into view), back in slowly (no pumping over steps).
  zoom_ += (want_zoom_ - zoom_) * (1.0f - std::exp(-(want_zoom_ > zoom_ ? 4.0f : 1.0f) * dt));
  // Fast horizontally so the creature never leaves the view; vertically slower going up (steps
  // do not shake the picture), faster going down (a drop's landing comes into view early).
  center_ws_.x += (t.x - center_ws_.x) * (1.0f - std::exp(-5.0f * dt));
  const float rate_y = t.y < center_ws_.y ? 6.0f : 3.0f;
  center_ws_.y += (t.y - center_ws_.y) * (1.0f - std::exp(-rate_y * dt));
  // Never let the creature leave the inner 80 % of the width.
  const float limit = 0.8f * hh * zoom_ * aspect;
  center_ws_.x = std::clamp(center_ws_.x, s.root_ws.x - limit, s.root_ws.x + limit);
  return center_ws_;
}

}  // namespace ossa
