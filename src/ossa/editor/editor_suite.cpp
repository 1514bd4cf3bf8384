#include "ossa/editor/editor_suite.h"

#include <algorithm>
#include <cmath>

#include <SDL.h>

#include "ossa/editor/editor_suite_internal.h"
#include "ossa/game/world.h"
#include "ossa/render/character_mesh.h"
#include "ossa/render/debug_draw.h"

namespace ossa {

namespace {
constexpr float kPollInterval = 0.5f;    // seconds between file polls (hot reload)
constexpr float kPickRadiusPx = 7.0f;    // handle / spawn pick tolerance in pixels

// Pixel (x right, y down) → world, the inverse of Camera2D::world_to_pixel.
glm::vec2 pixel_to_world(const Camera2D& c, glm::vec2 px, glm::vec2 viewport) {
  const glm::vec2 ndc{px.x / viewport.x * 2.0f - 1.0f, 1.0f - px.y / viewport.y * 2.0f};
  return c.center_ws + glm::vec2(ndc.x * c.half_height * c.aspect, ndc.y * c.half_height);
}
}  // namespace

EditorSuite::EditorSuite(World& world, const Generator* generator, EditorPaths paths)
    : world_(&world), generator_(generator), paths_(std::move(paths)),
      canvases_(new Canvas[3]) {
  level_ = std::make_unique<LevelEditorModel>(world.level(), undo_);
  if (!paths_.level_file.empty()) level_->set_path(paths_.level_file);
  World* w = world_;
  spline_ = std::make_unique<SplineEditorModel>(
      world.prototypes(), undo_, [w](const SplinePrototypes& p) { w->set_prototypes(p); });
  if (!paths_.prototypes_file.empty()) spline_->set_path(paths_.prototypes_file);
  tuning_ = std::make_unique<TuningModel>(world.params(), undo_,
                                          [w](const AnimatorParams& p) { w->set_params(p); });
  if (generator_) {
    creature_ = std::make_unique<CreaturePanelModel>(*generator_, undo_);
    creature_->on_apply_to_player = [w](std::shared_ptr<const Creature> c) {
      if (w->player()) {
        w->set_player_creature(std::move(c));
      } else {
        w->spawn_player(std::move(c), w->level().spawn_ws);
      }
    };
    creature_->on_spawn_npc = [w](std::shared_ptr<const Creature> c) {
      // A body length ahead of the player, on the ground its feet stand on (the reset searches
      // for ground from above that height), else at the spawn.
      glm::vec2 at = w->level().spawn_ws;
      if (const Player* p = w->player()) {
        const Animator& a = p->animator();
        at = {a.x() + a.facing() * (a.rig().body_front - a.rig().body_back), a.root_y() - a.rig().root_rest_y};
      }
      w->spawn_npc(std::move(c), at, 1000u + static_cast<uint64_t>(w->npc_count()));
    };
  }
  copy_to_buffer(level_path_buf_, sizeof level_path_buf_,
                 paths_.level_file.empty() ? paths_.levels_dir + "/new.json" : paths_.level_file);
  copy_to_buffer(tiled_path_buf_, sizeof tiled_path_buf_, paths_.export_dir + "/level.tiled.json");
  copy_to_buffer(proto_path_buf_, sizeof proto_path_buf_,
                 paths_.prototypes_file.empty() ? "prototypes.json" : paths_.prototypes_file);
  copy_to_buffer(genome_path_buf_, sizeof genome_path_buf_, paths_.genome_file);
  copy_to_buffer(gltf_path_buf_, sizeof gltf_path_buf_, paths_.export_dir + "/creature.gltf");
  copy_to_buffer(svg_path_buf_, sizeof svg_path_buf_, paths_.export_dir + "/creature.svg");
  copy_to_buffer(png_path_buf_, sizeof png_path_buf_, paths_.export_dir + "/creature.png");
  copy_to_buffer(tuning_path_buf_, sizeof tuning_path_buf_, paths_.tuning_file);
  tuning_->set_path(paths_.tuning_file);
  rig_ = std::make_unique<RigEditorModel>(undo_);
  if (!paths_.rig_file.empty()) (void)rig_->open_mapping(paths_.rig_file);  // an error shows in the window
  copy_to_buffer(rig_path_buf_, sizeof rig_path_buf_, paths_.rig_file.empty() ? paths_.export_dir + "/character.rig.json" : paths_.rig_file);
  copy_to_buffer(rig_mesh_buf_, sizeof rig_mesh_buf_, rig_->is_open() ? rig_->mapping().mesh_path : std::string());
  undo_.clear();
}

EditorSuite::~EditorSuite() = default;

Status EditorSuite::apply_character_to_player(const std::string& rig_path) {
  if (apply_character) return apply_character(rig_path);
  Result<LoadedCharacter> c = load_character(rig_path);
  if (!c.ok()) return c.error();
  if (world_->player()) {
    world_->set_player_character(c->character);
  } else {
    world_->spawn_player(c->character, world_->level().spawn_ws);
  }
  return {};
}

void EditorSuite::update(float dt) {
  if (const Player* p = world_->player()) tuning_->sample(p->animator(), dt);
  if (enabled && show_rig) rig_->step_preview(dt);
  level_files_age_ += dt;
  poll_timer_ += dt;
  if (poll_timer_ >= kPollInterval) {
    poll_timer_ = 0.0f;
    level_->poll_file();
    spline_->poll_file();
  }
}

bool EditorSuite::wants_keyboard() const {
  return ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantCaptureKeyboard;
}

bool EditorSuite::has_unsaved_changes() const {
  return undo_.any_dirty();
}

bool EditorSuite::request_quit() {
  if (!has_unsaved_changes()) return true;
  pending_discard_ = [this] { quit_confirmed_ = true; };
  open_discard_popup_ = true;
  return false;
}

void EditorSuite::confirm_discard(EditorDocument document, std::function<void()> action) {
  if (!undo_.is_dirty(document)) {
    action();
    return;
  }
  pending_discard_ = std::move(action);
  open_discard_popup_ = true;
}

bool EditorSuite::handle_mouse(glm::vec2 mouse_px, bool down, float /*wheel*/,
                               const Camera2D& camera, glm::vec2 viewport_px) {
  last_camera_ = camera;
  last_viewport_px_ = viewport_px;
  if (!enabled) {
    mouse_was_down_ = down;
    if (mouse_drag_) level_->end_drag();
    mouse_drag_ = false;
    hovered_box_.reset();
    return false;
  }
  const bool pressed = down && !mouse_was_down_;
  const bool released = !down && mouse_was_down_;
  mouse_was_down_ = down;
  // ImGui reports a mouse outside the window as -FLT_MAX: hold the drag where it is.
  const bool mouse_valid = std::abs(mouse_px.x) < 1e6f && std::abs(mouse_px.y) < 1e6f &&
                           viewport_px.x > 0.0f && viewport_px.y > 0.0f;
  if (!mouse_valid) {
    if (released && mouse_drag_) {
      level_->end_drag();
      mouse_drag_ = false;
    }
    return mouse_drag_;
  }
  const glm::vec2 p_ws = pixel_to_world(camera, mouse_px, viewport_px);
  const float radius_ws = kPickRadiusPx * 2.0f * camera.half_height / viewport_px.y;

  if (mouse_drag_) {  // a drag that started in the viewport owns the mouse until release
    if (released) {
      level_->end_drag();
      mouse_drag_ = false;
    } else {
      level_->drag_to(p_ws);
    }
    return true;
  }
  const bool imgui_has_mouse = ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse;
  if (!level_edit_mode || imgui_has_mouse) {
    hovered_box_.reset();
    return false;
  }
  const LevelHit hover = level_->hit_test(p_ws, radius_ws);
  hovered_box_ = hover.kind == LevelHit::Kind::kBox ? std::optional<int>(hover.box) : std::nullopt;
  if (pressed) {
    const LevelHit hit = level_->begin_drag(p_ws, radius_ws);
    mouse_drag_ = hit.kind != LevelHit::Kind::kNone;
    if (!mouse_drag_) level_->end_drag();
    return mouse_drag_;
  }
  return false;
}

void EditorSuite::draw_viewport(DebugDraw& debug) const {
  if (!enabled || !level_edit_mode) return;
  const Level& level = level_->level();
  const Box view = last_camera_.visible_box();
  // Grid: only when it is not denser than ~8 px per cell.
  const float g = level_->options.grid_size;
  const float px_per_m = last_viewport_px_.y / (2.0f * last_camera_.half_height);
  if (level_->options.snap && g > 0.0f && g * px_per_m >= 8.0f) {
    const glm::vec4 c{1.0f, 1.0f, 1.0f, 0.08f};
    for (float x = std::floor(view.min_ws.x / g) * g; x <= view.max_ws.x; x += g)
      debug.add_line({x, view.min_ws.y}, {x, view.max_ws.y}, c);
    for (float y = std::floor(view.min_ws.y / g) * g; y <= view.max_ws.y; y += g)
      debug.add_line({view.min_ws.x, y}, {view.max_ws.x, y}, c);
  }
  // A Tiled map or an LDtk level is drawn with its art, not its boxes (level_view.h): outline
  // the boxes in view, so what collides can be seen and picked.
  if (level.art && !level.art->empty()) {
    std::vector<int> in_view;
    level.overlapping(view, in_view);
    for (int i : in_view) debug.add_box(level.box(i), {1.0f, 1.0f, 1.0f, 0.45f});
  }
  if (hovered_box_ && *hovered_box_ < level.size() && hovered_box_ != level_->selected())
    debug.add_box(level.box(*hovered_box_), {1.0f, 1.0f, 0.6f, 0.9f});
  if (auto s = level_->selected(); s && *s < level.size()) {
    const Box& b = level.box(*s);
    debug.add_box(b, {1.0f, 0.75f, 0.1f, 0.25f}, true);
    debug.add_box(b, {1.0f, 0.75f, 0.1f, 1.0f});
    const float h = 4.0f / px_per_m;  // 8 px handles
    for (int i = 0; i < static_cast<int>(BoxHandle::kCount); ++i) {
      const glm::vec2 q = handle_position(b, static_cast<BoxHandle>(i));
      debug.add_box(Box::from_center(q, glm::vec2(h)), {1.0f, 1.0f, 1.0f, 1.0f}, true);
      debug.add_box(Box::from_center(q, glm::vec2(h)), {0.1f, 0.1f, 0.1f, 1.0f});
    }
  }
  // Spawn: a green flag pole with a cross at its foot. A spawn inside a box is red, with a
  // dashed line up to the free ground where the creature will stand instead.
  const glm::vec2 s = level.spawn_ws;
  const float r = kPickRadiusPx / px_per_m;
  const bool buried = level.spawn_inside_box();
  const glm::vec4 flag = buried ? glm::vec4(1.0f, 0.2f, 0.15f, 1.0f) : glm::vec4(0.2f, 1.0f, 0.3f, 1.0f);
  debug.add_line(s, s + glm::vec2(0.0f, 4.0f * r), flag);
  debug.add_triangle(s + glm::vec2(0.0f, 4.0f * r), s + glm::vec2(0.0f, 2.6f * r),
                     s + glm::vec2(2.0f * r, 3.3f * r), flag);
  debug.add_cross(s, r, flag);
  if (buried) {
    const glm::vec2 free = level.free_point_above(s);
    const float dash = std::max(r, (free.y - s.y) / 64.0f);  // at most 32 dashes
    for (float y = s.y; y < free.y; y += 2.0f * dash) {
      debug.add_line({s.x, y}, {s.x, std::min(y + dash, free.y)}, flag);
    }
    debug.add_cross(free, 0.6f * r, flag);
  }
}

void EditorSuite::handle_keys(std::span<const KeyChord> keys) {
  for (const KeyChord& k : keys) {
    if (k.key == SDLK_F2 && !k.ctrl && !k.alt) {
      enabled = !enabled;
      continue;
    }
    if (!enabled) continue;
    const bool context = ImGui::GetCurrentContext() != nullptr;
    if (context && ImGui::GetIO().WantTextInput) continue;  // the text field's own undo and keys
    if (k.ctrl && !k.alt && k.key == SDLK_z) {
      if (k.shift) undo_.redo(); else undo_.undo();
    } else if (k.ctrl && !k.alt && k.key == SDLK_y) {
      undo_.redo();
    } else if (k.ctrl && !k.alt && k.key == SDLK_s) {
      save_level();
    } else if (k.key == SDLK_DELETE && !k.ctrl && level_edit_mode && !(context && ImGui::GetIO().WantCaptureKeyboard)) {
      level_->delete_selected();
    }
  }
}

void EditorSuite::place_next_window(EditorWindow window) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const WindowRect r = editor_layout({display.x, display.y})[static_cast<size_t>(window)];
  const ImGuiCond cond = reset_layout_ ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
  ImGui::SetNextWindowPos(ImVec2(r.pos.x, r.pos.y), cond);
  ImGui::SetNextWindowSize(ImVec2(r.size.x, r.size.y), cond);
}

void EditorSuite::save_level() {
  LevelEditorModel& m = *level_;
  if (m.path().empty()) (void)m.save_as(level_path_buf_); else (void)m.save();
  refresh_level_files();
}

void EditorSuite::draw_ui() {
  if (!enabled) return;
  if (ImGui::BeginMainMenuBar()) {
    if (ImGui::BeginMenu("Edit")) {
      const std::string u = "Undo " + undo_.undo_label(), r = "Redo " + undo_.redo_label();
      if (ImGui::MenuItem(u.c_str(), "Ctrl+Z", false, undo_.can_undo())) undo_.undo();
      if (ImGui::MenuItem(r.c_str(), "Ctrl+Y", false, undo_.can_redo())) undo_.redo();
      if (ImGui::MenuItem("Save level", "Ctrl+S")) save_level();
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Windows")) {
      ImGui::MenuItem("Level editor", nullptr, &show_level);
      ImGui::MenuItem("Spline prototypes", nullptr, &show_splines);
      ImGui::MenuItem("Creature", nullptr, &show_creature);
      ImGui::MenuItem("Tuning", nullptr, &show_tuning);
      ImGui::MenuItem("Rig", nullptr, &show_rig);
      ImGui::MenuItem("Edit level in viewport", nullptr, &level_edit_mode);
      ImGui::Separator();
      if (ImGui::MenuItem("Reset layout")) reset_layout_ = true;
      ImGui::EndMenu();
    }
    if (has_unsaved_changes()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "  unsaved changes");
    ImGui::EndMainMenuBar();
  }
  if (show_level) draw_level_window();
  if (show_splines) draw_spline_window();
  if (show_creature) draw_creature_window();
  if (show_tuning) draw_tuning_window();
  if (show_rig) draw_rig_window();
  reset_layout_ = false;
  draw_popups();
}

void EditorSuite::draw_popups() {
  if (open_discard_popup_) {
    ImGui::OpenPopup("Discard unsaved changes?");
    open_discard_popup_ = false;
  }
  if (ImGui::BeginPopupModal("Discard unsaved changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted("There are unsaved changes. They will be lost.");
    for (int d = 0; d < kEditorDocumentCount; ++d) {
      static const char* kNames[] = {"level", "spline prototypes", "creature genome", "tuning", "rig mapping"};
      if (undo_.is_dirty(static_cast<EditorDocument>(d)))
        ImGui::BulletText("%s", kNames[d]);
    }
    if (ImGui::Button("Discard")) {
      auto action = std::move(pending_discard_);
      pending_discard_ = nullptr;
      if (action) action();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      pending_discard_ = nullptr;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

std::optional<glm::vec2> EditorSuite::spline_key_screen_px(SplineVersion version, int key) const {
  const Canvas& c = canvases_[static_cast<int>(version)];
  const auto& keys = spline_->spline(version).keys;
  if (!c.drawn || key < 0 || key >= static_cast<int>(keys.size())) return std::nullopt;
  const ImVec2 s = c.to_screen(spline_->key_position(version, key));
  return glm::vec2(s.x, s.y);
}

}  // namespace ossa
