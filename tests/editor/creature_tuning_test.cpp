#include <catch2/catch.hpp>

#include <filesystem>

#include "ossa/editor/creature_panel_model.h"
#include "ossa/editor/tuning_model.h"
#include "ossa/gen/genome.h"
#include "ossa/io/file.h"
#include "ossa/io/json.h"
#include "shared/scenes.h"

namespace ossa {
namespace {

namespace fs = std::filesystem;

std::string genome_text(const Genome& g) { return genome_to_json(g).dump(); }

TEST_CASE("creature panel: an edited genome is named custom, an example by its name", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  REQUIRE(m.creature());
  CHECK(m.creature()->name == "horse");
  m.set_sigma(0, 1.0);
  REQUIRE(m.creature());
  CHECK(m.creature()->name == "custom");
  undo.undo();
  CHECK(m.creature()->name == "horse");
  m.variation(0.5);
  CHECK(m.creature()->name == "custom");
  REQUIRE(m.pick_example("kangaroo").ok());
  CHECK(m.creature()->name == "kangaroo");
  m.regenerate(CreaturePart::kTail);
  CHECK(m.creature()->name == "custom");
  // Applied to a player: the player is named so too (the HUD's first line).
  std::shared_ptr<const Creature> applied;
  m.on_apply_to_player = [&](std::shared_ptr<const Creature> c) { applied = std::move(c); };
  m.apply_to_player();
  REQUIRE(applied);
  CHECK(applied->name == "custom");
}

TEST_CASE("creature panel: examples, random, conditions and undo steps", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  REQUIRE(m.creature());
  REQUIRE(m.genome().name == "horse");
  REQUIRE(m.example_names().size() == 44);
  REQUIRE_FALSE(m.dirty());
  const std::string horse = genome_text(m.genome());
  REQUIRE(m.pick_example("kangaroo").ok());
  REQUIRE_FALSE(m.pick_example("no such animal").ok());
  REQUIRE_FALSE(m.last_error().empty());
  m.seed = 9;
  GenerateOptions o;
  o.wings = 1;
  o.leg_pairs = 1;
  m.set_conditions(o);
  REQUIRE(m.genome().pca[kWings] == Approx(1.0).margin(0.5));
  REQUIRE(m.creature()->count(LimbKind::kWing) == 2);
  REQUIRE(undo.size() == 2);
  undo.undo();
  undo.undo();
  REQUIRE(genome_text(m.genome()) == horse);
  REQUIRE_FALSE(m.dirty());
}

TEST_CASE("creature panel: smooth skinning is a genome option, one undo step, kept for new creatures", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  REQUIRE(m.genome().options.smooth_skinning);  // the default
  REQUIRE(m.creature()->smooth_skinning);
  const std::string skeleton_before = genome_text(m.genome());
  m.set_smooth_skinning(false);
  REQUIRE(undo.size() == 1);
  REQUIRE(m.dirty());
  REQUIRE_FALSE(m.creature()->smooth_skinning);
  REQUIRE_FALSE(genome_to_json(m.genome())["options"]["smooth_skinning"].get<bool>());
  m.set_smooth_skinning(false);  // no change, no step
  REQUIRE(undo.size() == 1);
  m.random();  // new creatures keep the choice
  REQUIRE_FALSE(m.genome().options.smooth_skinning);
  undo.undo();
  undo.undo();
  REQUIRE(genome_text(m.genome()) == skeleton_before);
  REQUIRE(m.creature()->smooth_skinning);
}

TEST_CASE("creature panel: sigma sliders move one component, a drag is one step", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const Genome before = m.genome();
  const double s1 = m.sigma(1);
  m.begin_edit("PC1");
  for (int i = 0; i <= 10; ++i) m.set_sigma(0, -1.0 + 0.2 * i);
  m.end_edit();
  REQUIRE(undo.size() == 1);
  REQUIRE(m.sigma(0) == Approx(1.0).margin(0.05));
  REQUIRE(m.sigma(1) == Approx(s1).margin(0.05));  // the other components stay
  REQUIRE(m.genome().pca[kWings] == before.pca[kWings]);
  REQUIRE(m.genome().limbs.size() == before.limbs.size());
  REQUIRE(m.creature());
  m.set_sigma(0, 99.0);  // clamped
  REQUIRE(m.sigma(0) == Approx(CreaturePanelModel::kSigmaRange).margin(0.05));
  undo.undo();
  undo.undo();
  REQUIRE(genome_text(m.genome()) == genome_text(before));
}

TEST_CASE("creature panel: regenerating one part keeps the rest", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    m.seed = seed;
    for (CreaturePart part : {CreaturePart::kLimbs, CreaturePart::kRibs, CreaturePart::kTail, CreaturePart::kSkull}) {
      const Genome a = m.genome();
      m.regenerate(part);
      const Genome& b = m.genome();
      REQUIRE(b.pca == a.pca);
      REQUIRE(b.neck_vertebrae == a.neck_vertebrae);
      REQUIRE(b.back_vertebrae == a.back_vertebrae);
      if (part != CreaturePart::kTail) REQUIRE(b.tail_vertebrae == a.tail_vertebrae);
      if (part != CreaturePart::kRibs) REQUIRE(b.rib_interval == a.rib_interval);
      if (part != CreaturePart::kSkull) REQUIRE(b.skull_variant == a.skull_variant);
      if (part != CreaturePart::kLimbs) REQUIRE(genome_to_json(b)["limbs"] == genome_to_json(a)["limbs"]);
      REQUIRE(m.creature());
    }
  }
  REQUIRE(undo.size() <= 48);
  while (undo.undo()) {
  }
  REQUIRE(m.genome().name == "horse");
}

TEST_CASE("creature panel: genome save/load, SVG export, variation and callbacks", "[editor]") {
  UndoStack undo;
  CreaturePanelModel m(scenes::generator(), undo, "horse");
  const fs::path dir = fs::temp_directory_path() / "ossa_editor_test_creature";
  fs::remove_all(dir);
  fs::create_directories(dir);
  m.variation(0.8);
  REQUIRE(m.dirty());
  const std::string varied = genome_text(m.genome());
  REQUIRE(m.save_genome((dir / "g.json").string()).ok());
  REQUIRE_FALSE(m.dirty());
  REQUIRE(m.pick_example("kangaroo").ok());
  REQUIRE(m.load_genome((dir / "g.json").string()).ok());
  REQUIRE(genome_text(m.genome()) == varied);
  REQUIRE_FALSE(m.dirty());
  REQUIRE_FALSE(m.load_genome((dir / "none.json").string()).ok());
  REQUIRE(genome_text(m.genome()) == varied);
  REQUIRE(m.export_svg((dir / "c.svg").string()).ok());
  REQUIRE(read_file((dir / "c.svg").string()).value().find("<svg") != std::string::npos);
  REQUIRE_FALSE(m.save_genome((dir / "missing" / "g.json").string()).ok());
  int applied = 0, spawned = 0;
  m.on_apply_to_player = [&](std::shared_ptr<const Creature> c) { applied += c != nullptr; };
  m.on_spawn_npc = [&](std::shared_ptr<const Creature> c) { spawned += c != nullptr; };
  m.apply_to_player();
  m.spawn_npc();
  REQUIRE((applied == 1 && spawned == 1));
}

TEST_CASE("tuning: every field has a unit and a range holding its default, edits clamp and undo", "[editor]") {
  const AnimatorParams defaults;
  const auto fields = tuning_fields();
  REQUIRE(fields.size() == 25);  // every float of AnimatorParams (gait_override has a control of its own)
  for (const TuningField& f : fields) {
    INFO(f.name);
    REQUIRE(std::string(f.unit).size() > 0);
    REQUIRE(f.min < f.max);
    REQUIRE(defaults.*(f.member) >= f.min);
    REQUIRE(defaults.*(f.member) <= f.max);
  }
  UndoStack undo;
  AnimatorParams seen;
  TuningModel m(defaults, undo, [&](const AnimatorParams& p) { seen = p; });
  m.set_value(0, 100.0f);
  REQUIRE(m.params().step_distance_multiplier == fields[0].max);
  REQUIRE(seen.step_distance_multiplier == fields[0].max);
  m.begin_edit("duty");
  for (int i = 0; i < 10; ++i) m.set_value(3, 0.6f + 0.01f * i);
  m.end_edit();
  m.set_gait_override(GaitOverride::kTrot);
  REQUIRE(undo.size() == 3);
  while (undo.undo()) {
  }
  REQUIRE(seen.step_distance_multiplier == defaults.step_distance_multiplier);
  REQUIRE(seen.duty_walk == defaults.duty_walk);
  REQUIRE(seen.gait_override == GaitOverride::kAuto);
}

}  // namespace
}  // namespace ossa

namespace ossa {
namespace {

TEST_CASE("tuning: footfall history samples every leg per tick over the last seconds", "[editor]") {
  const Creature horse = scenes::quadruped();
  Level level({Box::from_corner(-10.0f, -1.0f, 200.0f, 1.0f)});
  Animator animator(horse, SplinePrototypes::defaults());
  animator.reset({0.0f, 1.0f}, level);
  UndoStack undo;
  TuningModel m(AnimatorParams{}, undo);
  m.history_seconds = 2.0f;
  const float dt = 1.0f / 120.0f;
  const float speed = 0.8f * animator.walk_speed();
  for (int i = 0; i < 6 * 120; ++i) {
    animator.update(dt, speed, level);
    m.sample(animator, dt);
  }
  REQUIRE(m.leg_count() == animator.leg_count());
  REQUIRE(m.sample_capacity() == 240);
  for (int leg = 0; leg < m.leg_count(); ++leg) {
    REQUIRE(static_cast<int>(m.leg_history(leg).size()) == 240);
    // The newest sample is the animator's current state.
    REQUIRE(m.leg_history(leg).back() == (animator.leg_state(leg) == LegState::kStance));
    // Walking: every leg both stands and swings within two seconds, mostly standing.
    const float f = m.stance_fraction(leg);
    REQUIRE(f > 0.4f);
    REQUIRE(f < 0.95f);
  }
  // Another creature (different leg count) restarts the history.
  const Creature biped = scenes::biped();
  Animator two(biped, SplinePrototypes::defaults());
  two.reset({0.0f, 1.0f}, level);
  m.sample(two, dt);
  REQUIRE(m.leg_count() == two.leg_count());
  REQUIRE(m.leg_history(0).size() == 1);
}

}  // namespace
}  // namespace ossa

namespace ossa {
namespace {

TEST_CASE("tuning: the footfall diagram of a quadruped at full run shows a gallop", "[editor]") {
  // A transverse gallop: the hind feet land one after the other, then the front feet, half a
  // cycle on (the trot's diagonal pairs would land together, a pair's feet half a cycle apart). Touch-downs read from the
  // footfall history, as phases of the cycle after the near hind foot's.
  const Creature horse = scenes::quadruped();
  Level level({Box::from_corner(-10.0f, -1.0f, 400.0f, 1.0f)});
  Animator animator(horse, SplinePrototypes::defaults());
  animator.reset({0.0f, 1.0f}, level);
  UndoStack undo;
  TuningModel m(AnimatorParams{}, undo);
  m.history_seconds = 2.0f;
  const float dt = 1.0f / 120.0f;
  for (int i = 0; i < 8 * 120; ++i) {
    animator.update(dt, animator.run_speed(), level);
    m.sample(animator, dt);
  }
  REQUIRE(animator.gait() == Gait::kGallop);
  const float period = 1.0f / (animator.cycle_frequency() * dt);  // samples per cycle
  auto last_touch_down = [&](int leg) {
    const std::deque<bool>& h = m.leg_history(leg);
    for (int k = static_cast<int>(h.size()) - 1; k > 0; --k) {
      if (h[k] && !h[k - 1]) return k;
    }
    return -1;
  };
  const AnimRig& rig = animator.rig();
  int near_hind = -1, far_hind = -1, near_front = -1, far_front = -1;
  for (int leg = 0; leg < animator.leg_count(); ++leg) {
    const bool front = rig.legs[leg].girdle == 0, near = rig.legs[leg].side == Side::kNear;
    (front ? (near ? near_front : far_front) : (near ? near_hind : far_hind)) = leg;
  }
  const int ref = last_touch_down(near_hind);
  REQUIRE(ref >= 0);
  auto phase = [&](int leg) {
    const int t = last_touch_down(leg);
    REQUIRE(t >= 0);
    const float d = static_cast<float>(t - ref) / period;
    return d - std::floor(d);
  };
  auto circular = [](float a, float b) { return std::min(std::fabs(a - b), 1.0f - std::fabs(a - b)); };
  INFO("far hind " << phase(far_hind) << " near front " << phase(near_front) << " far front " << phase(far_front));
  // Transverse gallop (gait_family.cpp): in both pairs the far foot lands a tenth of a cycle
  // after the near one (the same lead on both sides); the fore pair about half a cycle after
  // the hind pair.
  CHECK(circular(phase(far_hind), 0.1f) < 0.08f);
  CHECK(circular(phase(near_front), 0.45f) < 0.08f);
  CHECK(circular(phase(far_front), 0.55f) < 0.08f);
}

TEST_CASE("tuning: files round trip, bad values are reported, a failing save keeps the file", "[editor]") {
  const fs::path dir = fs::temp_directory_path() / "ossa_editor_test_tuning";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "t.json").string();
  UndoStack undo;
  AnimatorParams seen;
  TuningModel m(AnimatorParams{}, undo, [&](const AnimatorParams& p) { seen = p; });
  m.set_value(3, 0.7f);
  m.set_gait_override(GaitOverride::kGallop);
  REQUIRE(m.dirty());
  REQUIRE(m.save_as(path).ok());
  REQUIRE_FALSE(m.dirty());
  const std::string text = read_file(path).value();
  m.reset();
  REQUIRE(m.load(path).ok());
  REQUIRE(m.params().duty_walk == 0.7f);
  REQUIRE(m.params().gait_override == GaitOverride::kGallop);
  REQUIRE(seen.duty_walk == 0.7f);
  REQUIRE_FALSE(m.dirty());
  // Out of range and wrong format: errors name the file and field; params kept.
  REQUIRE(write_file_atomic((dir / "bad.json").string(),
                            R"({"format": "ossa.tuning", "version": 1, "params": {"duty_run": 5}})").ok());
  const Status bad = m.load((dir / "bad.json").string());
  REQUIRE_FALSE(bad.ok());
  REQUIRE(bad.message().find("duty_run") != std::string::npos);
  REQUIRE(m.params().duty_walk == 0.7f);
  REQUIRE_FALSE(load_params((dir / "missing.json").string()).ok());
  REQUIRE_FALSE(params_from_json(Json::array(), "x").ok());
  m.set_value(0, 1.5f);
  REQUIRE_FALSE(m.save_as((dir / "nope" / "t.json").string()).ok());
  REQUIRE_FALSE(m.last_error().empty());
  REQUIRE(read_file(path).value() == text);
  REQUIRE(m.dirty());
}


TEST_CASE("tuning: the documented range ends load (float ends, not their doubles)", "[editor]") {
  // stance_height's range is [0.7, 1.05]: a hand-written 1.05 was refused ("got 1.05") and
  // the whole file ignored.
  const Json doc = Json::parse(R"({"format": "ossa.tuning", "version": 1, "params": {"stance_height": 1.05}})");
  Result<AnimatorParams> p = params_from_json(doc, "t.json");
  INFO((p.ok() ? std::string() : p.message()));
  REQUIRE(p.ok());
  CHECK(p->stance_height == 1.05f);
  for (const TuningField& f : tuning_fields()) {
    for (const float end : {f.min, f.max}) {
      Json d = Json::parse(R"({"format": "ossa.tuning", "version": 1, "params": {}})");
      d["params"][f.name] = json_float(end);
      INFO(f.name << " = " << end);
      CHECK(params_from_json(d, "t.json").ok());
    }
  }
}

}  // namespace
}  // namespace ossa
