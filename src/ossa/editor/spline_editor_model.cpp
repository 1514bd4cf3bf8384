#include "ossa/editor/spline_editor_model.h"

#include <algorithm>
#include <cmath>

namespace ossa {

SplineEditorModel::SplineEditorModel(SplinePrototypes p, UndoStack& undo, ChangeFn on_change)
    : prototypes_(std::move(p)), undo_(&undo), on_change_(std::move(on_change)) {}

const HermiteSpline& SplineEditorModel::spline(SplineVersion v) const {
  return v == SplineVersion::kWalk ? pair().walk : pair().run;
}

HermiteSpline& SplineEditorModel::spline_mut(SplineVersion v) {
  return v == SplineVersion::kWalk ? prototypes_[current_].walk : prototypes_[current_].run;
}

glm::vec2 SplineEditorModel::key_position(SplineVersion v, int key) const {
  const HermiteKey& k = spline(v).keys[key];
  return {k.t, k.p};
}

glm::vec2 SplineEditorModel::tangent_position(SplineVersion v, int key) const {
  const HermiteKey& k = spline(v).keys[key];
  const float dt = tangent_side(v, key) * kTangentDt;
  return {k.t + dt, k.p + k.m * dt};
}

void SplineEditorModel::apply(const SplinePrototypes& p) {
  prototypes_ = p;
  if (on_change_) on_change_(prototypes_);
}

void SplineEditorModel::replace(const SplinePrototypes& p) {
  drag_.reset();
  selected_.reset();
  apply(p);
  undo_->clear(EditorDocument::kPrototypes);
}

void SplineEditorModel::push_change(const char* label, const SplinePrototypes& before, bool applied) {
  // Prototypes are a few hundred bytes: whole snapshots keep undo trivially exact.
  const SplinePrototypes after = prototypes_;
  if (applied) prototypes_ = before;  // push runs redo when not applied; keep one path
  undo_->push({label, EditorDocument::kPrototypes, [this, after] { apply(after); },
               [this, before] { apply(before); }},
              false);
}

void SplineEditorModel::begin_drag(const SplineHandle& h) {
  if (drag_) end_drag();
  const int n = static_cast<int>(spline(h.version).keys.size());
  if (h.key < 0 || h.key >= n) return;
  selected_ = h;
  drag_ = Drag{h, prototypes_};
}

void SplineEditorModel::drag_to(glm::vec2 tp) {
  if (!drag_ || !std::isfinite(tp.x) || !std::isfinite(tp.y)) return;
  HermiteSpline& s = spline_mut(drag_->handle.version);
  const int i = drag_->handle.key;
  const int n = static_cast<int>(s.keys.size());
  HermiteKey& k = s.keys[i];
  if (drag_->handle.part == SplineHandle::Part::kKey) {
    if (i == 0) {
      k.t = 0.0f;
    } else if (i == n - 1) {
      k.t = 1.0f;
    } else {
      k.t = std::clamp(tp.x, s.keys[i - 1].t + kMinKeyGap, s.keys[i + 1].t - kMinKeyGap);
    }
    k.p = prototype_range(current_).clamp(tp.y);
  } else {
    // The handle stays on its side of the key, so the slope never flips through a vertical.
    const float side = tangent_side(drag_->handle.version, i);
    const float dt = side * std::max(side * (tp.x - k.t), 0.01f);
    k.m = std::clamp((tp.y - k.p) / dt, -kMaxPrototypeTangent, kMaxPrototypeTangent);
  }
  if (on_change_) on_change_(prototypes_);
}

void SplineEditorModel::end_drag() {
  if (!drag_) return;
  const SplinePrototypes before = drag_->before;
  const bool key = drag_->handle.part == SplineHandle::Part::kKey;
  drag_.reset();
  const auto& a = before.pairs;
  const auto& b = prototypes_.pairs;
  bool changed = false;
  for (int i = 0; i < kPrototypeCount && !changed; ++i) {
    for (int v = 0; v < 2 && !changed; ++v) {
      const auto& ka = v ? a[i].run.keys : a[i].walk.keys;
      const auto& kb = v ? b[i].run.keys : b[i].walk.keys;
      changed = ka.size() != kb.size() ||
                !std::equal(ka.begin(), ka.end(), kb.begin(), [](const HermiteKey& x, const HermiteKey& y) {
                  return x.t == y.t && x.p == y.p && x.m == y.m;
                });
    }
  }
  if (changed) push_change(key ? "move key" : "change tangent", before, true);
}

int SplineEditorModel::add_key(float t) {
  if (!(t > 0.0f && t < 1.0f)) return -1;
  const SplinePrototypes before = prototypes_;
  int index = -1;
  for (SplineVersion v : {SplineVersion::kWalk, SplineVersion::kRun}) {
    HermiteSpline& s = spline_mut(v);
    auto it = std::lower_bound(s.keys.begin(), s.keys.end(), t,
                               [](const HermiteKey& k, float x) { return k.t < x; });
    const int i = static_cast<int>(it - s.keys.begin());
    // Walk and run may hold their keys at different t; the new key must fit in both at the
    // same index so the pair stays matched key by key.
    if (index >= 0 && i != index) { prototypes_ = before; return -1; }
    if ((it != s.keys.end() && it->t - t < kMinKeyGap) ||
        (it != s.keys.begin() && t - std::prev(it)->t < kMinKeyGap)) {
      prototypes_ = before;
      return -1;
    }
    float p = 0.0f, m = 0.0f;
    s.evaluate(t, &p, &m);
    s.keys.insert(it, HermiteKey{t, prototype_range(current_).clamp(p),
                                 std::clamp(m, -kMaxPrototypeTangent, kMaxPrototypeTangent)});
    index = i;
  }
  push_change("add key", before, true);
  selected_ = SplineHandle{SplineHandle::Part::kKey, SplineVersion::kWalk, index};
  return index;
}

bool SplineEditorModel::remove_key(int index) {
  const int n = static_cast<int>(pair().walk.keys.size());
  if (index <= 0 || index >= n - 1 || n <= 2) return false;
  const SplinePrototypes before = prototypes_;
  for (SplineVersion v : {SplineVersion::kWalk, SplineVersion::kRun}) {
    auto& keys = spline_mut(v).keys;
    keys.erase(keys.begin() + index);
  }
  push_change("remove key", before, true);
  selected_.reset();
  return true;
}

bool SplineEditorModel::set_key(SplineVersion v, int index, const HermiteKey& key) {
  const int n = static_cast<int>(spline(v).keys.size());
  if (index < 0 || index >= n) return false;
  const SplinePrototypes before = prototypes_;
  HermiteKey k = key;
  if (index == 0) k.t = 0.0f;
  if (index == n - 1) k.t = 1.0f;
  // Keys stay where the loader would read them back (and the walk cannot break).
  k.p = prototype_range(current_).clamp(k.p);
  k.m = std::clamp(k.m, -kMaxPrototypeTangent, kMaxPrototypeTangent);
  spline_mut(v).keys[index] = k;
  if (!spline(v).is_valid() || !prototypes_.is_valid()) {
    prototypes_ = before;
    return false;
  }
  push_change("edit key", before, true);
  return true;
}

Status SplineEditorModel::save() {
  if (path_.empty()) return fail(Error{"the prototypes have no file yet: use Save as"});
  return save_as(path_);
}

Status SplineEditorModel::save_as(const std::string& path) {
  Status s = save_prototypes(path, prototypes_);
  if (!s.ok()) return fail(s);
  set_path(path);
  undo_->mark_saved(EditorDocument::kPrototypes);
  error_.clear();
  note_ = "saved " + path;
  return s;
}

Status SplineEditorModel::load(const std::string& path) {
  auto loaded = load_prototypes(path);
  if (!loaded.ok()) return fail(Error{loaded.message()});
  replace(loaded.value());
  set_path(path);
  error_.clear();
  note_ = "loaded " + path;
  return {};
}

bool SplineEditorModel::poll_file() {
  if (!watch_.poll()) return false;
  if (dirty()) {
    note_ = path_ + " changed on disk; not reloaded over unsaved edits";
    return false;
  }
  auto loaded = load_prototypes(path_);
  if (!loaded.ok()) {
    error_ = "reload failed, keeping the current prototypes: " + loaded.message();
    return false;
  }
  replace(loaded.value());
  error_.clear();
  note_ = "reloaded " + path_;
  return true;
}

}  // namespace ossa
