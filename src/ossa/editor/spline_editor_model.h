#pragma once
// SplineEditorModel — the spline prototype editor without any UI (DESIGN.md §10, [T 4.4.2]):
// pick a prototype, drag a key or its tangent handle in the walk or the run version, add and
// remove keys (walk and run stay matched: a key added at t goes into both, a removed key
// leaves both), type exact numbers, preview the blend at a walk→run factor, save / load /
// revert. Every change goes to `on_change` at once (the suite passes World::set_prototypes),
// so the walking creature uses it in the next tick.
//
// Canvas coordinates are the spline's own (t, p). A tangent handle sits at
// key + s·(kTangentDt, m·kTangentDt), s = tangent_side() (right of its key, left for the last
// key); dragging it to (t, p) sets m = (p − p_key)/(t − t_key).
#include <functional>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "ossa/anim/spline_prototypes.h"
#include "ossa/editor/file_watch.h"
#include "ossa/editor/undo_stack.h"
#include "ossa/io/result.h"

namespace ossa {

enum class SplineVersion : int { kWalk, kRun };

struct SplineHandle {
  enum class Part { kKey, kTangent } part = Part::kKey;
  SplineVersion version = SplineVersion::kWalk;
  int key = -1;
};

class SplineEditorModel {
 public:
  static constexpr float kTangentDt = 0.08f;   // t-length of a drawn tangent handle
  static constexpr float kMinKeyGap = 0.01f;   // smallest t between neighbouring keys

  using ChangeFn = std::function<void(const SplinePrototypes&)>;
  SplineEditorModel(SplinePrototypes prototypes, UndoStack& undo, ChangeFn on_change = {});

  const SplinePrototypes& prototypes() const { return prototypes_; }
  PrototypeId current() const { return current_; }
  void pick(PrototypeId id) { current_ = id; selected_.reset(); }
  const PrototypePair& pair() const { return prototypes_[current_]; }
  const HermiteSpline& spline(SplineVersion v) const;
  std::optional<SplineHandle> selected() const { return selected_; }
  void select(std::optional<SplineHandle> h) { selected_ = h; }

  // Canvas position of a key / its tangent handle.
  glm::vec2 key_position(SplineVersion v, int key) const;
  glm::vec2 tangent_position(SplineVersion v, int key) const;
  // +1: the handle is drawn right of its key; -1 for the last key (at t = 1, so it stays on
  // the canvas).
  float tangent_side(SplineVersion v, int key) const {
    return key + 1 == static_cast<int>(spline(v).keys.size()) && key > 0 ? -1.0f : 1.0f;
  }

  // ---- Drags (one undo step each) --------------------------------------------------------
  void begin_drag(const SplineHandle& handle);
  // Moves the dragged key to (t, p) — t kept strictly between its neighbours, the end keys
  // pinned to t = 0 and 1 — or sets the tangent from the handle position.
  void drag_to(glm::vec2 tp);
  void end_drag();
  bool dragging() const { return drag_.has_value(); }

  // ---- Edits (each one undo step) --------------------------------------------------------
  // Inserts a key at t (strictly inside (0, 1), away from existing keys) into both walk and
  // run, each lying on its current curve (same value and slope), so the shape is unchanged.
  // Returns the new key's index or -1.
  int add_key(float t);
  // Removes key `index` from both versions (never the end keys; at least 2 keys remain).
  bool remove_key(int index);
  // Numeric edit; refused (false) if it would break the spline (t order, non-finite).
  bool set_key(SplineVersion v, int index, const HermiteKey& key);

  // The blended curve at the walk→run factor w in [0, 1].
  HermiteSpline preview(float w) const { return pair().blended(w); }

  // ---- Files ----------------------------------------------------------------------------
  const std::string& path() const { return path_; }
  void set_path(const std::string& path) { path_ = path; watch_.watch(path); }
  bool dirty() const { return undo_->is_dirty(EditorDocument::kPrototypes); }
  Status save();
  Status save_as(const std::string& path);
  Status load(const std::string& path);   // keeps the current prototypes on error
  Status revert() { return load(path_); }  // back to the file on disk
  bool poll_file();                        // hot reload, as LevelEditorModel::poll_file
  const std::string& last_error() const { return error_; }
  const std::string& last_note() const { return note_; }

  // Replaces everything (no undo step); used by load.
  void replace(const SplinePrototypes& p);

 private:
  HermiteSpline& spline_mut(SplineVersion v);
  void apply(const SplinePrototypes& p);          // set + notify
  void push_change(const char* label, const SplinePrototypes& before, bool applied);
  Status fail(const Status& s) { if (!s.ok()) error_ = s.message(); return s; }

  SplinePrototypes prototypes_;
  UndoStack* undo_;
  ChangeFn on_change_;
  PrototypeId current_ = PrototypeId::kLegSwingY;
  std::optional<SplineHandle> selected_;
  struct Drag {
    SplineHandle handle;
    SplinePrototypes before;
  };
  std::optional<Drag> drag_;
  std::string path_;
  FileWatch watch_;
  std::string error_, note_;
};

}  // namespace ossa
