#include "ossa/editor/level_editor_model.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "ossa/io/data_dir.h"
#include "ossa/io/file.h"
#include "ossa/level/level_io.h"
#include "ossa/math/rng.h"

namespace ossa {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  Level level{{Box::from_corner(0.0f, -1.0f, 20.0f, 1.0f), Box::from_corner(5.0f, 0.0f, 2.0f, 1.0f)},
              glm::vec2(1.0f, 0.0f), "test"};
  UndoStack undo;
  LevelEditorModel m{level, undo};
};

fs::path temp_dir(const char* name) {
  fs::path d = fs::temp_directory_path() / ("ossa_editor_test_" + std::string(name));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST_CASE("level editor: hit test finds handles, spawn and the topmost box", "[editor]") {
  Fixture f;
  REQUIRE(f.m.hit_test({6.0f, 0.5f}, 0.05f).kind == LevelHit::Kind::kBox);
  REQUIRE(f.m.hit_test({6.0f, 0.5f}, 0.05f).box == 1);
  REQUIRE(f.m.hit_test({10.0f, -0.5f}, 0.05f).box == 0);
  REQUIRE(f.m.hit_test({10.0f, 5.0f}, 0.05f).kind == LevelHit::Kind::kNone);
  REQUIRE(f.m.hit_test({1.0f, 0.1f}, 0.05f).kind == LevelHit::Kind::kSpawn);
  // Handles only for the selection.
  REQUIRE(f.m.hit_test({7.0f, 1.0f}, 0.05f).kind == LevelHit::Kind::kBox);
  f.m.select(1);
  const LevelHit h = f.m.hit_test({7.02f, 0.98f}, 0.05f);
  REQUIRE(h.kind == LevelHit::Kind::kHandle);
  REQUIRE(h.handle == BoxHandle::kTopRight);
  REQUIRE(f.m.hit_test({5.0f, 0.5f}, 0.05f).handle == BoxHandle::kLeft);
}

TEST_CASE("level editor: a move drag is one undo step and snaps to the grid", "[editor]") {
  Fixture f;
  f.m.options.grid_size = 0.5f;
  REQUIRE(f.m.begin_drag({6.0f, 0.5f}, 0.05f).kind == LevelHit::Kind::kBox);
  REQUIRE(f.m.selected() == 1);
  for (int i = 1; i <= 20; ++i) f.m.drag_to({6.0f + 0.13f * i, 0.5f + 0.07f * i});
  f.m.end_drag();
  // Moved by (2.6, 1.4): the corner snaps to the 0.5 grid.
  REQUIRE(f.level.box(1) == Box::from_corner(7.5f, 1.5f, 2.0f, 1.0f));
  REQUIRE(f.undo.size() == 1);
  REQUIRE(f.m.dirty());
  f.undo.undo();
  REQUIRE(f.level.box(1) == Box::from_corner(5.0f, 0.0f, 2.0f, 1.0f));
  REQUIRE_FALSE(f.m.dirty());
  f.undo.redo();
  REQUIRE(f.level.box(1).min_ws == glm::vec2(7.5f, 1.5f));
  // The level index follows the edit: queries find the moved box.
  REQUIRE(f.level.ground_height_below(8.0f, 3.0f, 5.0f)->height_ws == Approx(2.5f));
}

TEST_CASE("level editor: resize by handles keeps the opposite edges and a minimum size", "[editor]") {
  Fixture f;
  f.m.options.grid_size = 0.25f;
  f.m.select(1);
  REQUIRE(f.m.begin_drag({7.0f, 1.0f}, 0.05f).handle == BoxHandle::kTopRight);
  f.m.drag_to({8.1f, 2.4f});
  f.m.end_drag();
  REQUIRE(f.level.box(1) == Box{{5.0f, 0.0f}, {8.0f, 2.5f}});
  REQUIRE(f.m.begin_drag({5.0f, 1.25f}, 0.05f).handle == BoxHandle::kLeft);
  f.m.drag_to({20.0f, 1.25f});  // past the right edge: clamped to the minimum width
  f.m.end_drag();
  REQUIRE(f.level.box(1).width() == Approx(f.m.options.min_box_size));
  REQUIRE(f.level.box(1).max_ws == glm::vec2(8.0f, 2.5f));
  REQUIRE(f.undo.size() == 2);
  f.undo.undo();
  f.undo.undo();
  REQUIRE(f.level.box(1) == Box::from_corner(5.0f, 0.0f, 2.0f, 1.0f));
}

TEST_CASE("level editor: add, duplicate, delete, spawn and their undo", "[editor]") {
  Fixture f;
  const Level original = f.level;
  f.m.options.grid_size = 0.5f;
  const int a = f.m.add_box({10.1f, 2.1f}, {1.0f, 1.0f});
  REQUIRE(a == 2);
  REQUIRE(f.level.box(2) == Box::from_corner(9.5f, 1.5f, 1.0f, 1.0f));
  const int d = f.m.duplicate_selected();
  REQUIRE(d == 3);
  REQUIRE(f.level.box(3) == Box::from_corner(10.0f, 2.0f, 1.0f, 1.0f));  // one step up-right: a stair
  f.m.select(0);
  REQUIRE(f.m.delete_selected());
  REQUIRE(f.level.size() == 3);
  REQUIRE(f.level.box(0) == Box::from_corner(5.0f, 0.0f, 2.0f, 1.0f));
  f.m.set_spawn({3.0f, 0.0f});
  REQUIRE(f.m.set_box(0, Box::from_corner(4.0f, 0.0f, 1.0f, 1.0f)));
  REQUIRE_FALSE(f.m.set_box(0, Box{{1.0f, 1.0f}, {0.0f, 2.0f}}));  // invalid: refused
  REQUIRE(f.undo.size() == 5);
  while (f.undo.undo()) {
  }
  REQUIRE(f.level == original);  // deleting box 0 came back at index 0
  while (f.undo.redo()) {
  }
  REQUIRE(f.level.size() == 3);
  REQUIRE(f.level.spawn_ws == glm::vec2(3.0f, 0.0f));
}

TEST_CASE("level editor: snapping rounds to the grid and can be turned off", "[editor]") {
  Fixture f;
  Rng rng(3);
  for (int i = 0; i < 500; ++i) {
    const float g = static_cast<float>(rng.uniform(0.05, 2.0));
    const float v = static_cast<float>(rng.uniform(-100.0, 100.0));
    f.m.options.grid_size = g;
    f.m.options.snap = true;
    const float s = f.m.snap(v);
    REQUIRE(std::abs(s - v) <= 0.5f * g + 1e-4f);
    REQUIRE(std::abs(s / g - std::round(s / g)) < 1e-3f);
    f.m.options.snap = false;
    REQUIRE(f.m.snap(v) == v);
  }
}

TEST_CASE("level editor: save, load, unsaved marker and Tiled round trip", "[editor]") {
  Fixture f;
  const fs::path dir = temp_dir("level");
  const std::string path = (dir / "a.json").string();
  REQUIRE_FALSE(f.m.save().ok());  // no path yet
  f.m.add_box({3.0f, 3.0f}, {1.0f, 1.0f});
  REQUIRE(f.m.dirty());
  REQUIRE(f.m.save_as(path).ok());
  REQUIRE_FALSE(f.m.dirty());
  const Level saved = f.level;
  f.m.add_box({8.0f, 3.0f}, {1.0f, 1.0f});
  REQUIRE(f.m.dirty());
  REQUIRE(f.m.load(path).ok());
  REQUIRE(f.level == saved);
  REQUIRE_FALSE(f.m.dirty());
  REQUIRE_FALSE(f.undo.can_undo());
  const std::string tiled = (dir / "a.tiled.json").string();
  REQUIRE(f.m.export_tiled(tiled).ok());
  f.m.add_box({12.0f, 3.0f}, {1.0f, 1.0f});
  REQUIRE(f.m.import_tiled(tiled).ok());
  REQUIRE(f.level.colliders() == saved.colliders());
  REQUIRE(f.level.spawn_ws == saved.spawn_ws);
  REQUIRE(f.m.path().empty());  // an import is a new document
  REQUIRE(f.m.dirty());
  // A broken file: error reported, level kept.
  write_file_atomic((dir / "bad.json").string(), "{ not json").ok();
  const Level before = f.level;
  const Status s = f.m.load((dir / "bad.json").string());
  REQUIRE_FALSE(s.ok());
  REQUIRE(f.m.last_error().find("bad.json") != std::string::npos);
  REQUIRE(f.level == before);
}

TEST_CASE("level editor: a failing save leaves the old file intact and reports it", "[editor]") {
  Fixture f;
  const fs::path dir = temp_dir("failsave");
  const std::string path = (dir / "keep.json").string();
  REQUIRE(f.m.save_as(path).ok());
  const std::string old_text = read_file(path).value();
  f.m.add_box({3.0f, 3.0f}, {1.0f, 1.0f});
  // Into a missing folder.
  const Status missing = f.m.save_as((dir / "no_such_folder" / "x.json").string());
  REQUIRE_FALSE(missing.ok());
  REQUIRE_FALSE(f.m.last_error().empty());
  REQUIRE(f.m.path() == path);
  REQUIRE(f.m.dirty());
  // Over a folder.
  fs::create_directories(dir / "a_folder.json");
  REQUIRE_FALSE(f.m.save_as((dir / "a_folder.json").string()).ok());
  REQUIRE(fs::is_directory(dir / "a_folder.json"));
  // The saved file is untouched.
  REQUIRE(read_file(path).value() == old_text);
  REQUIRE(f.m.dirty());
}

TEST_CASE("level editor: hot reload picks up outside changes, keeps state on parse errors", "[editor]") {
  Fixture f;
  const fs::path dir = temp_dir("reload");
  const std::string path = (dir / "r.json").string();
  REQUIRE(f.m.save_as(path).ok());
  REQUIRE_FALSE(f.m.poll_file());  // our own save is not a change
  Level other = f.level;
  other.add_box(Box::from_corner(30.0f, 0.0f, 1.0f, 1.0f));
  REQUIRE(save_level(path, other).ok());
  fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(2));
  REQUIRE(f.m.poll_file());
  REQUIRE(f.level == other);
  // A broken edit on disk: the level stays, the error is shown.
  REQUIRE(write_file_atomic(path, "{\"format\": \"ossa.level\"").ok());
  fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(4));
  REQUIRE_FALSE(f.m.poll_file());
  REQUIRE(f.level == other);
  REQUIRE(f.m.last_error().find("reload failed") != std::string::npos);
  // A file nested 300 000 deep replacing the level (it crashed the game, losing the editor's
  // work): refused like any broken file.
  REQUIRE(write_file_atomic(path, "{\"format\": \"ossa.level\", \"name\": " + std::string(300000, '[') +
                                      std::string(300000, ']') + "}").ok());
  fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(5));
  REQUIRE_FALSE(f.m.poll_file());
  REQUIRE(f.level == other);
  REQUIRE(f.m.last_error().find("nested more than 256") != std::string::npos);
  // Unsaved edits are never overwritten by a reload.
  f.m.add_box({40.0f, 3.0f}, {1.0f, 1.0f});
  REQUIRE(save_level(path, other).ok());
  fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(6));
  REQUIRE_FALSE(f.m.poll_file());
  REQUIRE(f.level.size() == other.size() + 1);
}


TEST_CASE("level editor: Open reads Tiled and LDtk files, Save never writes over them", "[editor]") {
  Fixture f;
  const fs::path dir = temp_dir("tiled_open");
  const std::string src = ossa::data_path("tests/level/data/");
  // Copies, so that a wrong save could not touch the fixtures.
  for (const char* name : {"tiles_zlib.tmx", "terrain.tsx", "world.ldtk"}) fs::copy_file(src + name, dir / name);
  const std::string tmx = (dir / "tiles_zlib.tmx").string();
  const std::string before = read_file(tmx).value();
  REQUIRE(f.m.load(tmx).ok());
  REQUIRE(f.level == load_level(tmx).value());
  CHECK(f.level.size() == 5);
  f.m.add_box({3.0f, 3.0f}, {1.0f, 1.0f});
  const Status s = f.m.save();
  REQUIRE_FALSE(s.ok());
  CHECK_THAT(s.message(), Catch::Contains("is a tiled-xml file; use Save as"));
  CHECK(read_file(tmx).value() == before);
  const std::string out = (dir / "converted.json").string();
  REQUIRE(f.m.save_as(out).ok());
  CHECK(parse_level(read_file(out).value(), out).value() == f.level);
  // An LDtk level by name.
  const std::string ldtk = (dir / "world.ldtk").string() + "#Level_1";
  REQUIRE(f.m.load(ldtk).ok());
  CHECK(f.level.name == "Level_1");
  CHECK_FALSE(f.m.save().ok());
}

}  // namespace
}  // namespace ossa
