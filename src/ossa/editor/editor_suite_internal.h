#pragma once
// Internal helpers shared by the EditorSuite's window files (not installed API).
#include <cstdio>
#include <string>

#include <glm/vec2.hpp>
#include <imgui.h>

#include "ossa/editor/editor_suite.h"

namespace ossa {

// One spline canvas as drawn in the last frame: its screen rectangle and the (t, p) range it
// shows. The range is frozen while a drag is under way so the canvas does not rescale under
// the mouse.
struct EditorSuite::Canvas {
  ImVec2 origin{0.0f, 0.0f};   // top-left, screen pixels
  ImVec2 size{0.0f, 0.0f};
  float t_min = -0.05f, t_max = 1.05f;
  float p_min = -0.1f, p_max = 1.0f;
  bool drawn = false;

  ImVec2 to_screen(glm::vec2 tp) const {
    return {origin.x + (tp.x - t_min) / (t_max - t_min) * size.x,
            origin.y + (1.0f - (tp.y - p_min) / (p_max - p_min)) * size.y};
  }
  glm::vec2 to_curve(ImVec2 s) const {
    return {t_min + (s.x - origin.x) / size.x * (t_max - t_min),
            p_min + (1.0f - (s.y - origin.y) / size.y) * (p_max - p_min)};
  }
};

// Copies a std::string into a fixed ImGui text buffer.
inline void copy_to_buffer(char* buffer, size_t size, const std::string& text) {
  std::snprintf(buffer, size, "%s", text.c_str());
}

// Shows an error in red and a note in grey (when not empty).
inline void show_messages(const std::string& error, const std::string& note) {
  if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", error.c_str());
  if (!note.empty()) ImGui::TextDisabled("%s", note.c_str());
}

}  // namespace ossa
