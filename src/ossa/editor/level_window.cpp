// EditorSuite: the level editor window (file list, files, grid, selected box, spawn).
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "ossa/editor/editor_suite.h"
#include "ossa/editor/editor_suite_internal.h"
#include "ossa/game/world.h"

namespace ossa {

void EditorSuite::refresh_level_files() {
  level_files_.clear();
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(paths_.levels_dir, ec)) {
    // Every format load_level reads: ossa levels, Tiled maps, LDtk projects.
    const std::string ext = e.path().extension().string();
    if (ext == ".json" || ext == ".tmj" || ext == ".tmx" || ext == ".ldtk") level_files_.push_back(e.path().string());
  }
  std::sort(level_files_.begin(), level_files_.end());
  level_files_age_ = 0.0f;
}

void EditorSuite::draw_level_window() {
  LevelEditorModel& m = *level_;
  const std::string name = m.path().empty() ? std::string("(unsaved level)")
                                            : std::filesystem::path(m.path()).filename().string();
  const std::string title = "Level: " + name + (m.dirty() ? " *" : "") + "###level";
  place_next_window(EditorWindow::kLevel);
  if (!ImGui::Begin(title.c_str(), &show_level)) {
    ImGui::End();
    return;
  }
  if (level_files_age_ > 2.0f) refresh_level_files();

  ImGui::Checkbox("Edit in viewport", &level_edit_mode);
  ImGui::SameLine();
  ImGui::Checkbox("Snap", &m.options.snap);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  float grid = m.options.grid_size;
  if (ImGui::InputFloat("grid m", &grid, 0.0f, 0.0f, "%.3f") && grid > 0.001f) m.options.grid_size = grid;

  // ---- Files ----
  ImGui::TextUnformatted("levels/");
  if (ImGui::BeginListBox("##files", ImVec2(-1, 5 * ImGui::GetTextLineHeightWithSpacing()))) {
    for (const std::string& f : level_files_) {
      const bool current = f == m.path();
      const std::string label = std::filesystem::path(f).filename().string();
      if (ImGui::Selectable(label.c_str(), current) && !current) {
        copy_to_buffer(level_path_buf_, sizeof level_path_buf_, f);
        confirm_discard(EditorDocument::kLevel, [this, f] { (void)level_->load(f); });
      }
    }
    ImGui::EndListBox();
  }
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##path", level_path_buf_, sizeof level_path_buf_);
  if (ImGui::Button("Save")) save_level();
  ImGui::SameLine();
  if (ImGui::Button("Save as")) {
    (void)m.save_as(level_path_buf_);
    refresh_level_files();
  }
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    const std::string path = level_path_buf_;
    confirm_discard(EditorDocument::kLevel, [this, path] { (void)level_->load(path); });
  }
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##tiled", tiled_path_buf_, sizeof tiled_path_buf_);
  if (ImGui::Button("Import Tiled")) {
    const std::string path = tiled_path_buf_;
    confirm_discard(EditorDocument::kLevel, [this, path] { (void)level_->import_tiled(path); });
  }
  ImGui::SameLine();
  if (ImGui::Button("Export Tiled")) (void)m.export_tiled(tiled_path_buf_);
  show_messages(m.last_error(), m.last_note());
  ImGui::Separator();

  // ---- Boxes ----
  ImGui::Text("%d boxes", m.level().size());
  if (ImGui::Button("Add box")) {
    m.add_box(last_camera_.center_ws, glm::vec2(2.0f, 0.5f));
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!m.selected());
  if (ImGui::Button("Duplicate")) m.duplicate_selected();
  ImGui::SameLine();
  if (ImGui::Button("Delete")) m.delete_selected();
  ImGui::EndDisabled();
  if (auto s = m.selected(); s && *s < m.level().size()) {
    const Box b = m.level().box(*s);
    float xywh[4] = {b.min_ws.x, b.min_ws.y, b.width(), b.height()};
    ImGui::Text("Box %d", *s);
    if (ImGui::InputFloat4("x y w h", xywh, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue)) {
      if (xywh[2] > 0.0f && xywh[3] > 0.0f)
        m.set_box(*s, Box::from_corner(xywh[0], xywh[1], xywh[2], xywh[3]));
    }
  } else {
    ImGui::TextDisabled("Click a box in the viewport to select it;");
    ImGui::TextDisabled("drag it or its handles; Delete removes it.");
  }
  float spawn[2] = {m.level().spawn_ws.x, m.level().spawn_ws.y};
  if (ImGui::InputFloat2("spawn", spawn, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue))
    m.set_spawn({spawn[0], spawn[1]});
  if (m.level().spawn_inside_box()) {
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "The spawn is inside a box: creatures start");
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "on the free ground above it (red marker).");
  }
  if (ImGui::Button("Respawn player here") && world_->player()) {
    world_->player()->animator().reset(m.level().spawn_ws + glm::vec2(0.0f, 1.0f), m.level());
  }
  ImGui::End();
}

}  // namespace ossa
