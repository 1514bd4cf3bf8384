#pragma once
// EditorLayout — where the editor windows open (first use, and for the open windows after
// Windows > Reset layout),
// from the display's size alone (no ImGui here, so it is tested directly):
//
//   * a left column (the Level and Tuning windows) and a right column (Spline prototypes,
//     Creature, Rig), each at most a quarter (left) or a third (right) of the width, below the
//     menu bar and inside the display with a margin;
//   * the middle — where the camera keeps the player (camera_follow.h: the creature near the
//     centre, its feet in the lower part) — stays free; the HUD is hidden while the editors are
//     shown, so nothing covers it.
// Windows in the same column open over each other (the one used last is in front).

#include <array>

#include <glm/vec2.hpp>

namespace ossa {

enum class EditorWindow : int { kLevel, kTuning, kSplines, kCreature, kRig, kCount };
inline constexpr int kEditorWindowCount = static_cast<int>(EditorWindow::kCount);

struct WindowRect {
  glm::vec2 pos{0.0f};   // top-left, pixels (x right, y down)
  glm::vec2 size{0.0f};
};

inline constexpr float kMenuBarHeight = 24.0f;  // pixels kept free at the top
inline constexpr float kLayoutMargin = 8.0f;

// The first-use rectangle of every window for a display of `display` pixels (>= 1 x 1).
std::array<WindowRect, kEditorWindowCount> editor_layout(glm::vec2 display);

}  // namespace ossa
