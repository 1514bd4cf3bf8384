#include "ossa/editor/level_editor_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>
#include <vector>

#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "ossa/level/tiled.h"

#include <glm/common.hpp>

namespace ossa {

glm::vec2 handle_position(const Box& b, BoxHandle h) {
  const glm::vec2 c = b.center();
  switch (h) {
    case BoxHandle::kBottomLeft: return b.min_ws;
    case BoxHandle::kBottom: return {c.x, b.min_ws.y};
    case BoxHandle::kBottomRight: return {b.max_ws.x, b.min_ws.y};
    case BoxHandle::kRight: return {b.max_ws.x, c.y};
    case BoxHandle::kTopRight: return b.max_ws;
    case BoxHandle::kTop: return {c.x, b.max_ws.y};
    case BoxHandle::kTopLeft: return {b.min_ws.x, b.max_ws.y};
    case BoxHandle::kLeft: return {b.min_ws.x, c.y};
    default: return c;
  }
}

LevelEditorModel::LevelEditorModel(Level& level, UndoStack& undo, LevelEditorOptions opts)
    : options(opts), level_(&level), undo_(&undo) {}

void LevelEditorModel::select(std::optional<int> box) {
  if (box && (*box < 0 || *box >= level_->size())) box.reset();
  selected_ = box;
}

float LevelEditorModel::snap(float v) const {
  if (!options.snap || !(options.grid_size > 0.0f)) return v;
  return std::round(v / options.grid_size) * options.grid_size;
}

LevelHit LevelEditorModel::hit_test(glm::vec2 p, float r) const {
  LevelHit hit;
  if (selected_ && *selected_ < level_->size()) {
    const Box& b = level_->box(*selected_);
    for (int h = 0; h < static_cast<int>(BoxHandle::kCount); ++h) {
      const glm::vec2 q = handle_position(b, static_cast<BoxHandle>(h));
      if (std::abs(q.x - p.x) <= r && std::abs(q.y - p.y) <= r) {
        hit.kind = LevelHit::Kind::kHandle;
        hit.box = *selected_;
        hit.handle = static_cast<BoxHandle>(h);
        return hit;
      }
    }
  }
  // The spawn marker is drawn as a cross about 2 r tall above the spawn point.
  const glm::vec2 s = level_->spawn_ws;
  if (std::abs(p.x - s.x) <= 2.0f * r && p.y >= s.y - r && p.y <= s.y + 4.0f * r) {
    hit.kind = LevelHit::Kind::kSpawn;
    return hit;
  }
  // The index answers overlap queries; a tiny box around the point finds every box that
  // contains it (closed containment checked after).
  std::vector<int> found;
  level_->overlapping(Box{p - glm::vec2(1e-4f), p + glm::vec2(1e-4f)}, found);
  for (auto it = found.rbegin(); it != found.rend(); ++it) {
    if (level_->box(*it).contains(p)) {
      hit.kind = LevelHit::Kind::kBox;
      hit.box = *it;
      return hit;
    }
  }
  return hit;
}

LevelHit LevelEditorModel::begin_drag(glm::vec2 p, float r) {
  if (dragging()) end_drag();
  LevelHit hit = hit_test(p, r);
  drag_ = Drag{};
  drag_.hit = hit;
  drag_.start_ws = p;
  drag_.spawn_before = level_->spawn_ws;
  switch (hit.kind) {
    case LevelHit::Kind::kBox:
    case LevelHit::Kind::kHandle:
      selected_ = hit.box;
      drag_.box_before = level_->box(hit.box);
      break;
    case LevelHit::Kind::kSpawn: break;
    case LevelHit::Kind::kNone: selected_.reset(); break;
  }
  return hit;
}

void LevelEditorModel::drag_to(glm::vec2 p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
  const glm::vec2 d = p - drag_.start_ws;
  switch (drag_.hit.kind) {
    case LevelHit::Kind::kNone: return;
    case LevelHit::Kind::kSpawn: {
      const glm::vec2 s = snap(drag_.spawn_before + d);
      if (std::isfinite(s.x) && std::isfinite(s.y)) level_->spawn_ws = s;
      return;
    }
    case LevelHit::Kind::kBox: {
      // The corner snaps, so a moved box keeps its size and lands on the grid.
      const Box& b0 = drag_.box_before;
      const glm::vec2 min = snap(b0.min_ws + d);
      // Far from the origin a float cannot hold the size any more: refuse such a move.
      const Box moved{min, min + b0.size()};
      if (moved.is_valid()) level_->set_box(drag_.hit.box, moved);
      return;
    }
    case LevelHit::Kind::kHandle: {
      Box b = drag_.box_before;
      const int h = static_cast<int>(drag_.hit.handle);
      const float m = std::max(options.min_box_size, 1e-4f);
      const bool left = h == 0 || h == 6 || h == 7, right = h == 2 || h == 3 || h == 4;
      const bool bottom = h == 0 || h == 1 || h == 2, top = h == 4 || h == 5 || h == 6;
      if (left) b.min_ws.x = std::min(snap(b.min_ws.x + d.x), b.max_ws.x - m);
      if (right) b.max_ws.x = std::max(snap(b.max_ws.x + d.x), b.min_ws.x + m);
      if (bottom) b.min_ws.y = std::min(snap(b.min_ws.y + d.y), b.max_ws.y - m);
      if (top) b.max_ws.y = std::max(snap(b.max_ws.y + d.y), b.min_ws.y + m);
      if (b.is_valid()) level_->set_box(drag_.hit.box, b);
      return;
    }
  }
}

void LevelEditorModel::end_drag() {
  const Drag d = drag_;
  drag_ = Drag{};
  if (d.hit.kind == LevelHit::Kind::kSpawn) {
    const glm::vec2 after = level_->spawn_ws;
    if (after == d.spawn_before) return;
    Level* lv = level_;
    const glm::vec2 before = d.spawn_before;
    undo_->push({"move spawn", EditorDocument::kLevel, [lv, after] { lv->spawn_ws = after; },
                 [lv, before] { lv->spawn_ws = before; }},
                true);
  } else if (d.hit.kind == LevelHit::Kind::kBox || d.hit.kind == LevelHit::Kind::kHandle) {
    const Box after = level_->box(d.hit.box);
    if (after == d.box_before) return;
    push_set_box(d.hit.box, d.box_before, after,
                 d.hit.kind == LevelHit::Kind::kBox ? "move box" : "resize box", true);
  }
}

void LevelEditorModel::push_set_box(int index, const Box& before, const Box& after,
                                    const char* label, bool applied) {
  Level* lv = level_;
  undo_->push({label, EditorDocument::kLevel, [lv, index, after] { lv->set_box(index, after); },
               [lv, index, before] { lv->set_box(index, before); }},
              applied);
}

int LevelEditorModel::add_box(glm::vec2 center, glm::vec2 size) {
  size = glm::max(glm::vec2(std::max(options.min_box_size, 1e-4f)),
                  options.snap ? glm::max(snap(size), glm::vec2(options.grid_size)) : size);
  const glm::vec2 min = snap(center - 0.5f * size);
  const Box box{min, min + size};
  if (!box.is_valid()) return -1;
  Level* lv = level_;
  undo_->push({"add box", EditorDocument::kLevel, [lv, box] { lv->add_box(box); },
               [lv] { lv->remove_box(lv->size() - 1); }});
  selected_ = level_->size() - 1;
  return *selected_;
}

bool LevelEditorModel::delete_selected() {
  if (!selected_ || *selected_ >= level_->size()) return false;
  const int index = *selected_;
  const Box box = level_->box(index);
  Level* lv = level_;
  undo_->push({"delete box", EditorDocument::kLevel, [lv, index] { lv->remove_box(index); },
               [lv, index, box] {
                 // Level has no insert: rebuild with the box back at its index.
                 std::vector<Box> c = lv->colliders();
                 c.insert(c.begin() + index, box);
                 lv->set_colliders(std::move(c));
               }});
  selected_.reset();
  return true;
}

int LevelEditorModel::duplicate_selected() {
  if (!selected_ || *selected_ >= level_->size()) return -1;
  const float step = options.snap && options.grid_size > 0.0f ? options.grid_size : 1.0f;
  const Box box = level_->box(*selected_).translated(glm::vec2(step, step));
  Level* lv = level_;
  undo_->push({"duplicate box", EditorDocument::kLevel, [lv, box] { lv->add_box(box); },
               [lv] { lv->remove_box(lv->size() - 1); }});
  selected_ = level_->size() - 1;
  return *selected_;
}

bool LevelEditorModel::set_box(int index, const Box& box) {
  if (index < 0 || index >= level_->size() || !box.is_valid()) return false;
  const Box before = level_->box(index);
  if (before == box) return true;
  push_set_box(index, before, box, "edit box", false);
  return true;
}

void LevelEditorModel::set_spawn(glm::vec2 spawn) {
  const glm::vec2 before = level_->spawn_ws;
  if (before == spawn) return;
  Level* lv = level_;
  undo_->push({"move spawn", EditorDocument::kLevel, [lv, spawn] { lv->spawn_ws = spawn; },
               [lv, before] { lv->spawn_ws = before; }});
}

void LevelEditorModel::set_path(const std::string& path) {
  path_ = path;
  // "project.ldtk#Level" (load_level): watch the project file.
  std::error_code ec;
  const size_t hash = path.rfind('#');
  watch_.watch(hash != std::string::npos && !std::filesystem::exists(path, ec) ? path.substr(0, hash) : path);
}

void LevelEditorModel::replace_level(Level level) {
  if (dragging()) drag_ = Drag{};
  *level_ = std::move(level);
  selected_.reset();
  undo_->clear(EditorDocument::kLevel);
}

Status LevelEditorModel::save() {
  if (path_.empty()) return fail(Error{"the level has no file yet: use Save as"});
  // A Tiled map or LDtk project opened here stays the designer's file: Save never writes an
  // ossa level over it (Save as does, to another file).
  const std::string file = path_.substr(0, path_.rfind('#'));
  Result<std::string> text = read_file(file);
  const LevelFormat format = detect_level_format(text.ok() ? std::string_view(*text) : std::string_view(), file);
  if (format != LevelFormat::kOssa) {
    return fail(Error{path_ + " is a " + level_format_name(format) + " file; use Save as to write the level as an ossa level (.json)"});
  }
  return save_as(path_);
}

Status LevelEditorModel::save_as(const std::string& path) {
  Status s = save_level(path, *level_);
  if (!s.ok()) return fail(s);
  set_path(path);
  undo_->mark_saved(EditorDocument::kLevel);
  error_.clear();
  note_ = "saved " + path;
  return s;
}

Status LevelEditorModel::load(const std::string& path) {
  LevelLoadOptions o;
  o.pixels_per_metre = options.pixels_per_metre_tiled;
  auto loaded = load_level(path, o);
  if (!loaded.ok()) return fail(Error{loaded.message()});
  replace_level(std::move(loaded.value()));
  set_path(path);
  error_.clear();
  note_ = "loaded " + path;
  return {};
}

Status LevelEditorModel::import_tiled(const std::string& path) {
  auto text = read_file(path);
  if (!text.ok()) return fail(Error{text.message()});
  TiledOptions o;
  o.pixels_per_metre = options.pixels_per_metre_tiled;
  auto level = ossa::import_tiled(text.value(), path, o);
  if (!level.ok()) return fail(Error{level.message()});
  // An import is a new, unsaved level: keep it out of the level file it came from.
  Level before = *level_;
  replace_level(std::move(level.value()));
  path_.clear();
  watch_ = FileWatch{};
  Level* lv = level_;
  Level after = *level_;
  undo_->push({"import Tiled map", EditorDocument::kLevel, [lv, after] { *lv = after; },
               [lv, before] { *lv = before; }},
              true);
  error_.clear();
  note_ = "imported " + path;
  return {};
}

Status LevelEditorModel::export_tiled(const std::string& path) const {
  TiledOptions o;
  o.pixels_per_metre = options.pixels_per_metre_tiled;
  Status s = write_json_atomic(path, ossa::export_tiled(*level_, o));
  if (!s.ok()) const_cast<LevelEditorModel*>(this)->error_ = s.message();
  return s;
}

bool LevelEditorModel::poll_file() {
  if (!watch_.poll()) return false;
  if (dirty()) {
    note_ = path_ + " changed on disk; not reloaded over unsaved edits";
    return false;
  }
  LevelLoadOptions o;
  o.pixels_per_metre = options.pixels_per_metre_tiled;
  auto loaded = load_level(path_, o);
  if (!loaded.ok()) {
    error_ = "reload failed, keeping the current level: " + loaded.message();
    return false;
  }
  replace_level(std::move(loaded.value()));
  error_.clear();
  note_ = "reloaded " + path_;
  return true;
}

}  // namespace ossa
