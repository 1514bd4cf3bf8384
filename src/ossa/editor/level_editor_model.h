#pragma once
// LevelEditorModel — the level editor without any UI (DESIGN.md §10, [T 4.3]): selection,
// picking of boxes, resize handles and the spawn point in world space, move / resize by
// handle / add / delete / duplicate boxes with grid snapping, and level files (save, save as,
// load, Tiled import / export, hot reload). It edits the Level it is given in place — the
// World's level — so the creature keeps walking on the level being edited.
//
// Every edit is one UndoStack step (document kLevel); a drag (begin_drag … drag_to … end_drag)
// changes the level live and becomes a single step when it ends. File errors are returned as
// Status and kept in last_error() for the UI; nothing throws, and a failed save leaves the old
// file intact (write_file_atomic).
//
// Space: world metres, +x right, +y up. Pixel tolerances are the caller's business: pass
// `pick_radius_ws` = a few pixels converted to metres.
#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "ossa/editor/file_watch.h"
#include "ossa/editor/undo_stack.h"
#include "ossa/io/result.h"
#include "ossa/level/level.h"

namespace ossa {

struct LevelEditorOptions {
  bool snap = true;
  float grid_size = 0.25f;       // metres, > 0: snap step for positions and sizes
  float min_box_size = 0.05f;    // metres: resizing never makes a box thinner than this
  float pixels_per_metre_tiled = 32.0f;  // Tiled import / export scale (pixels per metre); also
                                         // load()'s --pixels-per-metre (level_load.h)
};

// Eight resize handles of the selected box, counter-clockwise from the bottom-left corner.
enum class BoxHandle : int { kBottomLeft, kBottom, kBottomRight, kRight, kTopRight, kTop, kTopLeft, kLeft, kCount };
// World position of a handle of `box`.
glm::vec2 handle_position(const Box& box, BoxHandle handle);

struct LevelHit {
  enum class Kind { kNone, kBox, kHandle, kSpawn } kind = Kind::kNone;
  int box = -1;                            // collider index (kBox, kHandle)
  BoxHandle handle = BoxHandle::kCount;    // kHandle
};

class LevelEditorModel {
 public:
  // `level` and `undo` must outlive the model.
  LevelEditorModel(Level& level, UndoStack& undo, LevelEditorOptions options = {});

  LevelEditorOptions options;
  const Level& level() const { return *level_; }

  // ---- Selection and picking ----------------------------------------------------------
  std::optional<int> selected() const { return selected_; }
  void select(std::optional<int> box);
  // What lies under p_ws: first a handle of the selected box (within pick_radius_ws), then
  // the spawn marker, then the topmost box containing the point (highest index: drawn last).
  LevelHit hit_test(glm::vec2 p_ws, float pick_radius_ws) const;

  // ---- Mouse drags (one undo step each) -------------------------------------------------
  // Starts a drag at p_ws: grabs a handle of the selection, the spawn point or a box (which
  // becomes selected); on empty space deselects. Returns what was grabbed.
  LevelHit begin_drag(glm::vec2 p_ws, float pick_radius_ws);
  // Moves / resizes what was grabbed so it follows the mouse (snapped to the grid).
  void drag_to(glm::vec2 p_ws);
  // Ends the drag: pushes one undo step if anything changed.
  void end_drag();
  bool dragging() const { return drag_.hit.kind != LevelHit::Kind::kNone; }

  // ---- Edits (each one undo step) ------------------------------------------------------
  // Adds a box of `size` centred at center_ws (snapped), selects it, returns its index.
  int add_box(glm::vec2 center_ws, glm::vec2 size);
  bool delete_selected();
  // Copies the selection one grid step (or 1 m without snapping) to the right and above;
  // selects the copy. Returns its index or -1.
  int duplicate_selected();
  // Numeric edit of one box (invalid boxes are refused: false).
  bool set_box(int index, const Box& box);
  void set_spawn(glm::vec2 spawn_ws);
  float snap(float v) const;
  glm::vec2 snap(glm::vec2 p) const { return {snap(p.x), snap(p.y)}; }

  // ---- Files ----------------------------------------------------------------------------
  const std::string& path() const { return path_; }   // "" until saved or loaded
  void set_path(const std::string& path);
  bool dirty() const { return undo_->is_dirty(EditorDocument::kLevel); }
  Status save();                                      // to path(); refuses a Tiled/LDtk path()
  Status save_as(const std::string& path);
  // Replaces the level (undo history of the level is dropped). On error the level is kept.
  // Any format load_level reads: ossa levels, Tiled .tmj/.tmx, LDtk "project.ldtk#Level".
  Status load(const std::string& path);
  Status import_tiled(const std::string& path);       // the result is unsaved (no path)
  Status export_tiled(const std::string& path) const;
  // Hot reload: when path() changed on disk, reloads it — unless there are unsaved edits
  // (then only reports it) or it does not parse (keeps the level, reports the error).
  // Returns true when the level was reloaded.
  bool poll_file();
  // Message of the last failed file operation, or a note ("reloaded …"); "" when none.
  const std::string& last_error() const { return error_; }
  const std::string& last_note() const { return note_; }
  void clear_messages() { error_.clear(); note_.clear(); }

 private:
  Status fail(const Status& s) { if (!s.ok()) error_ = s.message(); return s; }
  void replace_level(Level level);
  void push_set_box(int index, const Box& before, const Box& after, const char* label, bool applied);

  Level* level_;
  UndoStack* undo_;
  std::optional<int> selected_;
  std::string path_;
  FileWatch watch_;
  std::string error_, note_;
  struct Drag {
    LevelHit hit;
    glm::vec2 start_ws{0.0f};
    Box box_before;
    glm::vec2 spawn_before{0.0f};
  } drag_;
};

}  // namespace ossa
