#pragma once
// TuningModel — the tuning panel without any UI (DESIGN.md §10): every AnimatorParams field
// with its unit and range, the gait override, and a footfall history (stance / swing of each
// leg over the last seconds, sampled once per tick) for the live footfall diagram.
//
// Edits are UndoStack steps (document kTuning; a slider drag is one step through
// begin_edit / end_edit) and go to `on_change` at once (the suite passes World::set_params).
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "ossa/anim/animator.h"
#include "ossa/anim/animator_params.h"
#include "ossa/editor/undo_stack.h"
#include "ossa/io/json_fwd.h"
#include "ossa/io/result.h"

namespace ossa {

// One tunable float of AnimatorParams.
struct TuningField {
  const char* name;                 // the member's name
  const char* unit;                 // "m/s^2", "rad", "x stride", ... (ASCII: ImGui's default font)
  float min, max;                   // slider range (values are clamped to it)
  float AnimatorParams::*member;
  const char* help;                 // one line for the tooltip
};
// Every float field of AnimatorParams, in declaration order.
std::span<const TuningField> tuning_fields();

// Tuning files (an editor format; the game may load one at start):
//   { "format": "ossa.tuning", "version": 1, "gait_override": "auto" | "walk" | "trot" | "gallop",
//     "params": { "<field name>": number, ... } }
// Fields left out keep their defaults; values must lie in the field's range; unknown fields
// are ignored. Errors name the file and the field.
Json params_to_json(const AnimatorParams& params);
Result<AnimatorParams> params_from_json(const Json& doc, std::string_view file);
Result<AnimatorParams> load_params(const std::string& path);
Status save_params(const std::string& path, const AnimatorParams& params);  // atomic

class TuningModel {
 public:
  using ChangeFn = std::function<void(const AnimatorParams&)>;
  TuningModel(AnimatorParams params, UndoStack& undo, ChangeFn on_change = {});

  const AnimatorParams& params() const { return params_; }
  float value(int field) const { return params_.*(tuning_fields()[field].member); }
  // Sets field `field` (index into tuning_fields()), clamped to its range.
  void set_value(int field, float value);
  void set_gait_override(GaitOverride gait);
  // The gait family the player moves by (kAuto: its creature's own), with undo.
  void set_gait_family(GaitFamily family);
  // Back to AnimatorParams{} (one step).
  void reset();
  void begin_edit(const std::string& label);
  void end_edit();
  // Replaces the params without an undo step (e.g. the game changed them).
  void replace(const AnimatorParams& p) { params_ = p; }

  // Files (document kTuning): save marks the tuning saved; load is one undo step and keeps
  // the params on error. Errors also stay in last_error().
  const std::string& path() const { return path_; }
  void set_path(const std::string& path) { path_ = path; }
  bool dirty() const { return undo_->is_dirty(EditorDocument::kTuning); }
  Status save_as(const std::string& path);
  Status load(const std::string& path);
  const std::string& last_error() const { return error_; }

  // ---- Footfall history ------------------------------------------------------------------
  float history_seconds = 4.0f;     // how far back the diagram reaches
  // One sample of every leg of `animator`, `dt` seconds after the previous one. A change in
  // the leg count (another creature) restarts the history.
  void sample(const Animator& animator, float dt);
  void clear_history();
  int leg_count() const { return static_cast<int>(legs_.size()); }
  // Stance (true) or swing of leg i, oldest first; one entry per sample.
  const std::deque<bool>& leg_history(int leg) const { return legs_[leg]; }
  int sample_capacity() const { return capacity_; }
  float sample_dt() const { return dt_; }
  // Fraction of the samples of leg i in stance (the measured duty factor).
  float stance_fraction(int leg) const;
  Gait gait() const { return gait_; }

 private:
  void push(const AnimatorParams& before, const char* label);

  AnimatorParams params_;
  UndoStack* undo_;
  ChangeFn on_change_;
  bool editing_ = false;
  AnimatorParams edit_before_;
  std::string edit_label_;
  std::vector<std::deque<bool>> legs_;
  int capacity_ = 0;
  float dt_ = 1.0f / 120.0f;
  Gait gait_ = Gait::kIdle;
  std::string path_, error_;
};

}  // namespace ossa
