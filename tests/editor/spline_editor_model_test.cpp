#include "ossa/editor/spline_editor_model.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include "ossa/io/file.h"
#include "ossa/math/rng.h"

namespace ossa {
namespace {

namespace fs = std::filesystem;

bool same_keys(const HermiteSpline& a, const HermiteSpline& b) {
  if (a.keys.size() != b.keys.size()) return false;
  for (size_t i = 0; i < a.keys.size(); ++i)
    if (a.keys[i].t != b.keys[i].t || a.keys[i].p != b.keys[i].p || a.keys[i].m != b.keys[i].m) return false;
  return true;
}
bool same(const SplinePrototypes& a, const SplinePrototypes& b) {
  for (int i = 0; i < kPrototypeCount; ++i)
    if (!same_keys(a.pairs[i].walk, b.pairs[i].walk) || !same_keys(a.pairs[i].run, b.pairs[i].run)) return false;
  return true;
}

struct Fixture {
  UndoStack undo;
  int notified = 0;
  SplinePrototypes seen;
  SplineEditorModel m{SplinePrototypes::defaults(), undo, [this](const SplinePrototypes& p) {
                        ++notified;
                        seen = p;
                      }};
};

TEST_CASE("spline editor: a key drag is one undo step and reaches the world at once", "[editor]") {
  Fixture f;
  f.m.pick(PrototypeId::kLegSwingY);
  const SplinePrototypes before = f.m.prototypes();
  REQUIRE(f.m.pair().walk.keys.size() >= 3);
  f.m.begin_drag({SplineHandle::Part::kKey, SplineVersion::kWalk, 1});
  for (int i = 0; i < 10; ++i) f.m.drag_to({0.45f, 0.3f + 0.01f * i});
  REQUIRE(f.notified >= 10);  // live while dragging
  REQUIRE(f.seen.pairs[int(PrototypeId::kLegSwingY)].walk.keys[1].p == Approx(0.39f));
  f.m.end_drag();
  REQUIRE(f.undo.size() == 1);
  REQUIRE(f.m.dirty());
  REQUIRE(f.m.prototypes().is_valid());
  f.undo.undo();
  REQUIRE(same(f.m.prototypes(), before));
  REQUIRE(same(f.seen, before));  // the world got the undo too
  REQUIRE_FALSE(f.m.dirty());
}

TEST_CASE("spline editor: dragged keys keep strict t order and pinned ends", "[editor]") {
  Fixture f;
  Rng rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    f.m.pick(static_cast<PrototypeId>(trial % kPrototypeCount));
    const auto v = trial % 2 ? SplineVersion::kRun : SplineVersion::kWalk;
    const int n = static_cast<int>(f.m.spline(v).keys.size());
    const int k = static_cast<int>(rng.uniform(0.0, n - 0.001));
    f.m.begin_drag({trial % 3 ? SplineHandle::Part::kKey : SplineHandle::Part::kTangent, v, k});
    f.m.drag_to({static_cast<float>(rng.uniform(-1.0, 2.0)), static_cast<float>(rng.uniform(-2.0, 2.0))});
    f.m.end_drag();
    REQUIRE(f.m.prototypes().is_valid());
    REQUIRE(f.m.spline(v).keys.front().t == 0.0f);
    REQUIRE(f.m.spline(v).keys.back().t == 1.0f);
  }
}

TEST_CASE("spline editor: tangent handle sets the slope", "[editor]") {
  Fixture f;
  f.m.pick(PrototypeId::kPelvisY);
  const glm::vec2 k = f.m.key_position(SplineVersion::kRun, 0);
  f.m.begin_drag({SplineHandle::Part::kTangent, SplineVersion::kRun, 0});
  f.m.drag_to(k + glm::vec2(0.1f, 0.05f));
  f.m.end_drag();
  REQUIRE(f.m.spline(SplineVersion::kRun).keys[0].m == Approx(0.5f));
  REQUIRE(f.m.tangent_position(SplineVersion::kRun, 0).y ==
          Approx(k.y + 0.5f * SplineEditorModel::kTangentDt));
}

TEST_CASE("spline editor: added and removed keys stay matched in walk and run", "[editor]") {
  Fixture f;
  Rng rng(5);
  for (int p = 0; p < kPrototypeCount; ++p) {
    f.m.pick(static_cast<PrototypeId>(p));
    for (int i = 0; i < 20; ++i) {
      const float t = static_cast<float>(rng.uniform(0.02, 0.98));
      const HermiteSpline walk_before = f.m.pair().walk, run_before = f.m.pair().run;
      const int idx = f.m.add_key(t);
      REQUIRE(f.m.pair().walk.keys.size() == f.m.pair().run.keys.size());
      if (idx < 0) continue;
      REQUIRE(f.m.pair().walk.keys[idx].t == t);
      REQUIRE(f.m.pair().run.keys[idx].t == t);
      // The shape is unchanged by an added key.
      for (int s = 0; s <= 20; ++s) {
        const float x = s / 20.0f;
        REQUIRE(f.m.pair().walk.position(x) == Approx(walk_before.position(x)).margin(1e-4));
        REQUIRE(f.m.pair().run.position(x) == Approx(run_before.position(x)).margin(1e-4));
      }
    }
    while (f.m.remove_key(1)) REQUIRE(f.m.pair().walk.keys.size() == f.m.pair().run.keys.size());
    REQUIRE(f.m.pair().walk.keys.size() == 2);
    REQUIRE_FALSE(f.m.remove_key(0));
    REQUIRE(f.m.prototypes().is_valid());
  }
  while (f.undo.undo()) {
  }
  REQUIRE(same(f.m.prototypes(), SplinePrototypes::defaults()));
}

TEST_CASE("spline editor: numeric edits are validated, preview blends walk and run", "[editor]") {
  Fixture f;
  f.m.pick(PrototypeId::kLegSwingY);
  const auto& w = f.m.pair().walk.keys;
  REQUIRE_FALSE(f.m.set_key(SplineVersion::kWalk, 1, {w[2].t + 0.1f, 0.0f, 0.0f}));  // out of order
  REQUIRE(f.undo.size() == 0);
  REQUIRE(f.m.set_key(SplineVersion::kWalk, 1, {w[1].t, 0.42f, 0.0f}));
  REQUIRE(f.m.pair().walk.keys[1].p == 0.42f);
  for (float blend : {0.0f, 0.3f, 1.0f}) {
    const HermiteSpline b = f.m.preview(blend);
    for (int s = 0; s <= 10; ++s) {
      const float t = s / 10.0f;
      if (blend == 0.0f) REQUIRE(b.position(t) == Approx(f.m.pair().walk.position(t)).margin(1e-5));
      if (blend == 1.0f) REQUIRE(b.position(t) == Approx(f.m.pair().run.position(t)).margin(1e-5));
    }
  }
}

TEST_CASE("spline editor: save, revert, load errors and a failing save", "[editor]") {
  Fixture f;
  const fs::path dir = fs::temp_directory_path() / "ossa_editor_test_splines";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "p.json").string();
  REQUIRE(f.m.save_as(path).ok());
  const std::string text = read_file(path).value();
  f.m.pick(PrototypeId::kArmSwing);
  REQUIRE(f.m.add_key(0.37f) >= 0);
  REQUIRE(f.m.dirty());
  REQUIRE_FALSE(f.m.save_as((dir / "missing" / "p.json").string()).ok());
  REQUIRE_FALSE(f.m.last_error().empty());
  REQUIRE(read_file(path).value() == text);
  REQUIRE(f.m.revert().ok());
  REQUIRE(same(f.m.prototypes(), SplinePrototypes::defaults()));
  REQUIRE(same(f.seen, SplinePrototypes::defaults()));
  REQUIRE_FALSE(f.m.dirty());
  REQUIRE(write_file_atomic((dir / "bad.json").string(), "[1, 2").ok());
  REQUIRE_FALSE(f.m.load((dir / "bad.json").string()).ok());
  REQUIRE(f.m.path() == path);
  // Hot reload of an outside change.
  SplinePrototypes other = SplinePrototypes::defaults();
  other[PrototypeId::kIdleY].walk.keys[0].p += 0.01f;
  other[PrototypeId::kIdleY].walk.keys.back().p += 0.01f;
  REQUIRE(save_prototypes(path, other).ok());
  fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(2));
  REQUIRE(f.m.poll_file());
  REQUIRE(same(f.m.prototypes(), other));
}

}  // namespace
}  // namespace ossa

namespace ossa {
namespace {

TEST_CASE("spline editor: the last key's tangent handle sits left of it and stays on its side", "[editor]") {
  UndoStack undo;
  SplineEditorModel m(SplinePrototypes::defaults(), undo);
  m.pick(PrototypeId::kLegSwingY);
  const int last = static_cast<int>(m.spline(SplineVersion::kWalk).keys.size()) - 1;
  REQUIRE(m.tangent_side(SplineVersion::kWalk, last) == -1.0f);
  REQUIRE(m.tangent_position(SplineVersion::kWalk, last).x < 1.0f);
  const glm::vec2 k = m.key_position(SplineVersion::kWalk, last);
  m.begin_drag({SplineHandle::Part::kTangent, SplineVersion::kWalk, last});
  m.drag_to(k + glm::vec2(-0.1f, 0.05f));
  REQUIRE(m.spline(SplineVersion::kWalk).keys[last].m == Approx(-0.5f));
  m.drag_to(k + glm::vec2(0.2f, 0.05f));  // crossing to the other side: clamped
  REQUIRE(std::isfinite(m.spline(SplineVersion::kWalk).keys[last].m));
  REQUIRE(m.spline(SplineVersion::kWalk).keys[last].m < 0.0f);
  m.end_drag();
  REQUIRE(undo.size() == 1);
}

}  // namespace
}  // namespace ossa
