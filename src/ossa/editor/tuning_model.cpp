#include "ossa/editor/tuning_model.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "ossa/io/file.h"
#include "ossa/io/json.h"

namespace ossa {

std::span<const TuningField> tuning_fields() {
  using P = AnimatorParams;
  // Ranges as documented in animator_params.h; the tail and crawl fields have none there,
  // so these are wide bounds around the defaults.
  static const std::array<TuningField, 25> kFields = {{
      {"step_distance_multiplier", "x stride", 0.3f, 2.0f, &P::step_distance_multiplier, "[T] scales the stride λ = 2.3·h·Fr^0.3"},
      {"interpolation_speed_multiplier", "x", 0.1f, 5.0f, &P::interpolation_speed_multiplier, "[T] how fast lean, height and gait blend ease"},
      {"max_spine_rotation", "rad", 0.0f, 0.6f, &P::max_spine_rotation, "[T] largest forward lean at full run"},
      {"duty_walk", "of cycle", 0.5f, 0.85f, &P::duty_walk, "fraction of a cycle a foot is down, walking"},
      {"duty_run", "of cycle", 0.2f, 0.6f, &P::duty_run, "same at a full run; < 0.5 gives a flight phase"},
      {"run_froude_start", "Fr", 0.05f, 3.0f, &P::run_froude_start, "Froude number where walk→run starts"},
      {"run_froude_end", "Fr", 0.05f, 3.0f, &P::run_froude_end, "Froude number where the blend reaches run"},
      {"gait_froude_scale", "x Fr", 0.3f, 3.0f, &P::gait_froude_scale, "scales the Froude numbers where the family's gaits change"},
      {"max_step_up", "x height", 0.05f, 1.0f, &P::max_step_up, "highest step up, of the shortest girdle's standing height (or 0.8 of a crouching leg's reach)"},
      {"max_step_down", "x height", 0.05f, 1.0f, &P::max_step_down, "deepest step down, of the standing height"},
      {"stance_height", "x rest", 0.7f, 1.05f, &P::stance_height, "girdle height, of its rest height"},
      {"stop_ease_time", "s", 0.05f, 0.3f, &P::stop_ease_time, "time for swinging feet to set down after a stop"},
      {"tail_stiffness", "1/s^2", 1.0f, 400.0f, &P::tail_stiffness, "spring stiffness of the tail's follow-through"},
      {"tail_damping", "ratio", 0.0f, 2.0f, &P::tail_damping, "damping ratio of the tail"},
      {"tail_max_swing", "rad", 0.0f, 1.5f, &P::tail_max_swing, "largest swing of the tail's spring"},
      {"crawl_amplitude", "of half length", 0.0f, 0.2f, &P::crawl_amplitude, "lift of a legless body's travelling wave"},
      {"crawl_waves", "waves/body", 0.25f, 4.0f, &P::crawl_waves, "waves along a legless body"},
      {"fin_beat", "rad", 0.0f, 0.5f, &P::fin_beat, "amplitude of a fin's slow beat while moving"},
      {"idle_period", "s", 0.5f, 10.0f, &P::idle_period, "period of the idle breathing"},
      {"jump_height", "x hip", 0.1f, 4.0f, &P::jump_height, "how high a jump lifts the body, in hip heights (a small creature's: at least this many half metres)"},
      {"jump_crouch", "x hip", 0.0f, 0.5f, &P::jump_crouch, "how low the body crouches before a jump"},
      {"jump_crouch_time", "x sqrt(h/g)", 0.5f, 4.0f, &P::jump_crouch_time, "how long the crouch lasts (follows the size)"},
      {"landing_compression", "x hip", 0.0f, 0.5f, &P::landing_compression, "how far the legs give landing from one hip height"},
      {"hard_landing", "x hip", 1.0f, 100.0f, &P::hard_landing, "a fall of more hip heights is a hard landing (a small creature's: more than this many half metres)"},
      {"gravity", "m/s^2", 1.0f, 30.0f, &P::gravity, "gravity of the Froude number and of falls"},
  }};
  return kFields;
}

TuningModel::TuningModel(AnimatorParams params, UndoStack& undo, ChangeFn on_change)
    : params_(params), undo_(&undo), on_change_(std::move(on_change)) {}

void TuningModel::push(const AnimatorParams& before, const char* label) {
  const AnimatorParams after = params_;
  undo_->push({label, EditorDocument::kTuning,
               [this, after] { params_ = after; if (on_change_) on_change_(params_); },
               [this, before] { params_ = before; if (on_change_) on_change_(params_); }},
              true);
}

void TuningModel::set_value(int field, float v) {
  const auto fields = tuning_fields();
  if (field < 0 || field >= static_cast<int>(fields.size()) || !std::isfinite(v)) return;
  const TuningField& f = fields[field];
  const AnimatorParams before = params_;
  params_.*(f.member) = std::clamp(v, f.min, f.max);
  if (params_.*(f.member) == before.*(f.member)) return;
  if (on_change_) on_change_(params_);
  if (!editing_) push(before, f.name);
}

void TuningModel::set_gait_override(GaitOverride gait) {
  if (params_.gait_override == gait) return;
  const AnimatorParams before = params_;
  params_.gait_override = gait;
  if (on_change_) on_change_(params_);
  if (!editing_) push(before, "gait override");
}

void TuningModel::set_gait_family(GaitFamily family) {
  if (params_.gait_family == family) return;
  const AnimatorParams before = params_;
  params_.gait_family = family;
  if (on_change_) on_change_(params_);
  if (!editing_) push(before, "gait family");
}

void TuningModel::reset() {
  const AnimatorParams before = params_;
  params_ = AnimatorParams{};
  if (on_change_) on_change_(params_);
  push(before, "reset tuning");
}

void TuningModel::begin_edit(const std::string& label) {
  if (editing_) return;
  editing_ = true;
  edit_before_ = params_;
  edit_label_ = label;
}

void TuningModel::end_edit() {
  if (!editing_) return;
  editing_ = false;
  if (edit_before_ == params_) return;
  const AnimatorParams before = edit_before_;
  const AnimatorParams after = params_;
  const std::string label = edit_label_;
  undo_->push({label, EditorDocument::kTuning,
               [this, after] { params_ = after; if (on_change_) on_change_(params_); },
               [this, before] { params_ = before; if (on_change_) on_change_(params_); }},
              true);
}

void TuningModel::sample(const Animator& animator, float dt) {
  if (dt > 0.0f) dt_ = dt;
  capacity_ = std::max(1, static_cast<int>(std::ceil(history_seconds / dt_)));
  gait_ = animator.gait();
  const int n = animator.leg_count();
  if (n != leg_count()) legs_.assign(n, {});
  for (int i = 0; i < n; ++i) {
    auto& h = legs_[i];
    h.push_back(animator.leg_state(i) == LegState::kStance);
    while (static_cast<int>(h.size()) > capacity_) h.pop_front();
  }
}

void TuningModel::clear_history() { legs_.clear(); }

float TuningModel::stance_fraction(int leg) const {
  const auto& h = legs_[leg];
  if (h.empty()) return 0.0f;
  return static_cast<float>(std::count(h.begin(), h.end(), true)) / static_cast<float>(h.size());
}

namespace {
const char* kGaitNames[] = {"auto", "walk", "trot", "gallop"};
}  // namespace

Json params_to_json(const AnimatorParams& p) {
  Json doc;
  doc["format"] = "ossa.tuning";
  doc["version"] = 1;
  doc["gait_override"] = kGaitNames[static_cast<int>(p.gait_override) + 1];
  doc["gait_family"] = gait_family_name(p.gait_family);
  Json fields = Json::object();
  for (const TuningField& f : tuning_fields()) fields[f.name] = p.*(f.member);
  doc["params"] = fields;
  return doc;
}

Result<AnimatorParams> params_from_json(const Json& doc, std::string_view file) {
  JsonReader r{std::string(file)};
  if (!r.expect_object(doc, "")) return r.error();
  if (r.string(doc, "", "format") != "ossa.tuning") r.fail("format", "expected \"ossa.tuning\"");
  r.integer(doc, "", "version", 1, 1);
  AnimatorParams p;
  const std::string gait = r.string_or(doc, "", "gait_override", "auto");
  if (r.failed()) return r.error();
  bool known = false;
  for (int i = 0; i < 4; ++i) {
    if (gait == kGaitNames[i]) {
      p.gait_override = static_cast<GaitOverride>(i - 1);
      known = true;
    }
  }
  if (!known) return Error::at(file, "gait_override", "expected auto, walk, trot or gallop, got \"" + gait + "\"");
  const std::string family = r.string_or(doc, "", "gait_family", "auto");
  if (r.failed()) return r.error();
  if (!parse_gait_family(family, &p.gait_family)) {
    return Error::at(file, "gait_family", "expected auto, cursorial, pacer, graviportal, bounder, hopper, sprawler, biped, bird, "
                                          "multi_leg or legless, got \"" + family + "\"");
  }
  if (r.has(doc, "params")) {
    const Json* fields = r.object(doc, "", "params");
    if (!fields) return r.error();
    for (const TuningField& f : tuning_fields()) {
      if (!r.has(*fields, f.name)) continue;
      p.*(f.member) = r.number_f(*fields, "params", f.name, f.min, f.max);
    }
  }
  if (r.failed()) return r.error();
  return p;
}

Result<AnimatorParams> load_params(const std::string& path) {
  auto doc = read_json_file(path);
  if (!doc.ok()) return doc.error();
  return params_from_json(doc.value(), path);
}

Status save_params(const std::string& path, const AnimatorParams& params) {
  return write_json_atomic(path, params_to_json(params));
}

Status TuningModel::save_as(const std::string& path) {
  Status s = save_params(path, params_);
  if (!s.ok()) {
    error_ = s.message();
    return s;
  }
  path_ = path;
  error_.clear();
  undo_->mark_saved(EditorDocument::kTuning);
  return s;
}

Status TuningModel::load(const std::string& path) {
  auto p = load_params(path);
  if (!p.ok()) {
    error_ = p.message();
    return p.error();
  }
  const AnimatorParams before = params_;
  params_ = p.value();
  if (on_change_) on_change_(params_);
  push(before, "load tuning");
  path_ = path;
  error_.clear();
  undo_->mark_saved(EditorDocument::kTuning);
  return {};
}

}  // namespace ossa
