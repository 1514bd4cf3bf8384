#include "ossa/editor/undo_stack.h"

#include <catch2/catch.hpp>

#include "ossa/math/rng.h"

namespace ossa {
namespace {

Command set_int(int& target, int value, EditorDocument doc = EditorDocument::kLevel) {
  const int before = target;
  return {"set", doc, [&target, value] { target = value; }, [&target, before] { target = before; }};
}

TEST_CASE("undo stack: do, undo, redo and the redo tail", "[editor]") {
  UndoStack u;
  int x = 0;
  u.push(set_int(x, 1));
  u.push(set_int(x, 2));
  REQUIRE(x == 2);
  REQUIRE(u.undo());
  REQUIRE(x == 1);
  REQUIRE(u.undo());
  REQUIRE(x == 0);
  REQUIRE_FALSE(u.undo());
  REQUIRE(u.redo());
  REQUIRE(x == 1);
  u.push(set_int(x, 5));  // drops the redo of "2"
  REQUIRE_FALSE(u.can_redo());
  REQUIRE(u.undo());
  REQUIRE(x == 1);
}

TEST_CASE("undo stack: a group and an already applied drag are one step", "[editor]") {
  UndoStack u;
  int x = 0, y = 0;
  u.begin_group("pair", EditorDocument::kPrototypes);
  u.push(set_int(x, 3, EditorDocument::kPrototypes));
  u.push(set_int(y, 4, EditorDocument::kPrototypes));
  u.end_group();
  REQUIRE(u.size() == 1);
  REQUIRE(u.undo_label() == "pair");
  u.undo();
  REQUIRE((x == 0 && y == 0));
  u.redo();
  REQUIRE((x == 3 && y == 4));
  // A drag changes the value live many times and pushes one applied command at the end.
  const int before = x;
  for (int i = 0; i < 30; ++i) x = 100 + i;
  const int after = x;
  u.push({"drag", EditorDocument::kLevel, [&x, after] { x = after; }, [&x, before] { x = before; }}, true);
  REQUIRE(u.size() == 2);
  u.undo();
  REQUIRE(x == 3);
  // An empty group adds no step.
  u.begin_group("nothing", EditorDocument::kLevel);
  u.end_group();
  REQUIRE(u.size() == 2);
}

TEST_CASE("undo stack: unsaved markers are exact per document", "[editor]") {
  UndoStack u;
  int a = 0, b = 0;
  REQUIRE_FALSE(u.any_dirty());
  u.push(set_int(a, 1, EditorDocument::kLevel));
  REQUIRE(u.is_dirty(EditorDocument::kLevel));
  REQUIRE_FALSE(u.is_dirty(EditorDocument::kPrototypes));
  u.mark_saved(EditorDocument::kLevel);
  REQUIRE_FALSE(u.is_dirty(EditorDocument::kLevel));
  u.push(set_int(b, 1, EditorDocument::kPrototypes));
  REQUIRE_FALSE(u.is_dirty(EditorDocument::kLevel));  // another document's edit
  u.push(set_int(a, 2, EditorDocument::kLevel));
  REQUIRE(u.is_dirty(EditorDocument::kLevel));
  u.undo();
  REQUIRE_FALSE(u.is_dirty(EditorDocument::kLevel));  // back at the saved state
  u.undo();
  u.undo();
  REQUIRE(u.is_dirty(EditorDocument::kLevel));        // before the saved state
  u.redo();
  REQUIRE_FALSE(u.is_dirty(EditorDocument::kLevel));
  // Undo then a different edit: dirty even though the step count matches.
  u.push(set_int(a, 7, EditorDocument::kLevel));
  REQUIRE(u.is_dirty(EditorDocument::kLevel));
  u.clear(EditorDocument::kLevel);
  REQUIRE_FALSE(u.is_dirty(EditorDocument::kLevel));
  u.clear();
  REQUIRE_FALSE(u.any_dirty());
  REQUIRE(u.size() == 0);
}

TEST_CASE("undo stack: clearing one document keeps the others' steps", "[editor]") {
  UndoStack u;
  int a = 0, b = 0;
  u.push(set_int(a, 1, EditorDocument::kLevel));
  u.push(set_int(b, 1, EditorDocument::kGenome));
  u.push(set_int(a, 2, EditorDocument::kLevel));
  u.clear(EditorDocument::kLevel);
  REQUIRE(u.size() == 1);
  REQUIRE(u.undo());
  REQUIRE(b == 0);
  REQUIRE(a == 2);
}

TEST_CASE("undo stack: random edit/undo/redo sequences match a reference history", "[editor]") {
  Rng rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    UndoStack u;
    int x = 0;
    std::vector<int> history{0};  // values after each applied step
    int cursor = 0;
    for (int op = 0; op < 200; ++op) {
      const float r = static_cast<float>(rng.uniform());
      if (r < 0.5f) {
        const int v = static_cast<int>(rng.uniform(0.0, 1000.0));
        u.push(set_int(x, v));
        history.resize(cursor + 1);
        history.push_back(v);
        ++cursor;
      } else if (r < 0.75f) {
        REQUIRE(u.undo() == (cursor > 0));
        if (cursor > 0) --cursor;
      } else {
        REQUIRE(u.redo() == (cursor + 1 < static_cast<int>(history.size())));
        if (cursor + 1 < static_cast<int>(history.size())) ++cursor;
      }
      REQUIRE(x == history[cursor]);
    }
  }
}

}  // namespace
}  // namespace ossa
