#include "ossa/editor/editor_layout.h"

#include <algorithm>

namespace ossa {

std::array<WindowRect, kEditorWindowCount> editor_layout(glm::vec2 display) {
  const float w = std::max(display.x, 1.0f), h = std::max(display.y, 1.0f);
  const float top = std::min(kMenuBarHeight + kLayoutMargin, 0.2f * h);
  const float bottom = h - kLayoutMargin;
  const float tall = std::max(bottom - top, 1.0f);
  // Column widths: wide enough for the windows' fields where the display allows it.
  const float left_w = std::clamp(0.25f * w, std::min(260.0f, 0.25f * w), 340.0f);
  const float right_w = std::clamp(0.33f * w, std::min(320.0f, 0.33f * w), 540.0f);
  const float left_x = std::min(kLayoutMargin, 0.02f * w);
  const float right_x = w - right_w - left_x;
  std::array<WindowRect, kEditorWindowCount> r{};
  const auto at = [&](EditorWindow win) -> WindowRect& { return r[static_cast<size_t>(win)]; };
  at(EditorWindow::kLevel) = {{left_x, top}, {left_w, std::min(480.0f, tall)}};
  at(EditorWindow::kTuning) = {{left_x, top}, {left_w, std::min(660.0f, tall)}};
  at(EditorWindow::kSplines) = {{right_x, top}, {right_w, std::min(560.0f, tall)}};
  at(EditorWindow::kCreature) = {{right_x, top}, {right_w, std::min(680.0f, tall)}};
  at(EditorWindow::kRig) = {{right_x, top}, {right_w, std::min(760.0f, tall)}};
  return r;
}

}  // namespace ossa
