// RigEditorModel (the Rig window without ImGui): a mapping opened with its mesh, parts given
// to bones by picking a part and clicking a bone (a leg in three clicks), errors naming the
// field and bone while the mapping cannot build, undo and redo, atomic saves that load back,
// a mesh opened without a mapping (guessed), and the preview standing and walking.

#include <catch2/catch.hpp>

#include <filesystem>
#include <unistd.h>

#include "ossa/editor/rig_editor_model.h"
#include "ossa/io/json.h"
#include "shared/scenes.h"

using namespace ossa;
namespace fs = std::filesystem;

namespace {

std::string humanoid() { return scenes::source_path("assets/characters/humanoid.rig.json"); }

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("ossa_rig_editor_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("the rig model opens a mapping with its mesh: bone tree, parts and the character", "[editor][rig]") {
  UndoStack undo;
  RigEditorModel m(undo);
  CHECK_FALSE(m.is_open());
  CHECK_FALSE(m.save().ok());  // nothing to save
  REQUIRE(m.open_mapping(humanoid()).ok());
  REQUIRE(m.character());
  CHECK(m.error().empty());
  CHECK(m.character()->rig->legs.size() == 2);
  REQUIRE(m.roots().size() == 1);
  CHECK(m.skeleton().bones[static_cast<size_t>(m.roots()[0])].name == "pelvis");
  CHECK(m.part_of(m.skeleton().find("thigh_l")) == "legs[0].upper");
  CHECK(m.part_of(m.skeleton().find("chest")) == "spine[1]");
  CHECK(m.bone_of({RigSlotKind::kArmHand, 1}) == m.skeleton().find("hand_r"));
  CHECK_FALSE(m.dirty());
  CHECK_FALSE(m.open_mapping("no/such.rig.json").ok());
  CHECK_THAT(m.last_error(), Catch::Contains("no/such.rig.json"));
  CHECK(m.character());  // the open document stays
}

TEST_CASE("a leg is three clicks, a mapping that cannot build says why, undo and redo", "[editor][rig]") {
  UndoStack undo;
  RigEditorModel m(undo);
  REQUIRE(m.open_mapping(humanoid()).ok());
  // Clearing the far foot: the character cannot build, and the error names the field.
  m.clear({RigSlotKind::kLegFoot, 1});
  CHECK_FALSE(m.character());
  CHECK_THAT(m.error(), Catch::Contains("legs[1].foot"));
  CHECK(m.dirty());
  REQUIRE(undo.undo());
  CHECK(m.character());
  CHECK_FALSE(m.dirty());
  REQUIRE(undo.redo());
  CHECK_FALSE(m.character());
  REQUIRE(undo.undo());

  // Remove the far leg and click it back together: upper, lower, foot.
  m.remove_leg(1);
  REQUIRE(m.mapping().legs.size() == 1);
  CHECK(m.character());  // one leg walks too
  m.add_leg();
  CHECK(m.slot() == RigSlot{RigSlotKind::kLegUpper, 1});
  CHECK_FALSE(m.character());  // an empty leg
  m.assign(m.slot(), m.skeleton().find("thigh_r"));
  CHECK(m.slot() == RigSlot{RigSlotKind::kLegLower, 1});
  m.assign(m.slot(), m.skeleton().find("shin_r"));
  CHECK(m.slot() == RigSlot{RigSlotKind::kLegFoot, 1});
  m.assign(m.slot(), m.skeleton().find("foot_r"));
  INFO(m.error());
  REQUIRE(m.character());
  CHECK(m.character()->rig->legs.size() == 2);
  CHECK(m.mapping().legs[1].side == Side::kFar);
  CHECK(undo.size() == 5);  // remove, add, three assignments

  // A bone given a second part leaves its first: legs[0] loses its thigh.
  m.assign({RigSlotKind::kLegUpper, 1}, m.skeleton().find("thigh_l"));
  CHECK(m.mapping().legs[0].upper.empty());
  CHECK_FALSE(m.character());
  CHECK_THAT(m.error(), Catch::Contains("legs[0].upper"));
  REQUIRE(undo.undo());
  CHECK(m.mapping().legs[0].upper == "thigh_l");

  // Lists append at the end slot and lose a bone that moves elsewhere.
  m.assign({RigSlotKind::kTail, 0}, m.skeleton().find("neck"));
  CHECK(m.mapping().tail == std::vector<std::string>{"neck"});
  CHECK(m.mapping().neck.empty());
  REQUIRE(undo.undo());
  CHECK(m.mapping().neck == std::vector<std::string>{"neck"});
  m.set_side(true, 0, Side::kFar);
  CHECK(m.mapping().legs[0].side == Side::kFar);
  m.set_contact(0, glm::vec2(0.15f, 0.0f));
  REQUIRE(m.mapping().legs[0].contact);
  CHECK(m.mapping().legs[0].contact->x == 0.15f);
}

TEST_CASE("the rig model saves atomically, the saved mapping loads back and builds", "[editor][rig]") {
  UndoStack undo;
  RigEditorModel m(undo);
  REQUIRE(m.open_mapping(humanoid()).ok());
  m.set_side(false, 1, Side::kNear);
  REQUIRE(m.dirty());
  const std::string path = (temp_dir() / "mine.rig.json").string();
  REQUIRE(m.save_as(path).ok());
  CHECK_FALSE(m.dirty());
  CHECK(m.path() == path);
  RigEditorModel back(undo);
  REQUIRE(back.open_mapping(path).ok());  // "mesh" now points from the new folder to the mesh
  REQUIRE(back.character());
  CHECK(back.mapping().arms[1].side == Side::kNear);
  CHECK(rig_mapping_to_json(back.mapping()) == rig_mapping_to_json(m.mapping()));
  CHECK_FALSE(m.save_as((temp_dir() / "no/such/dir/x.rig.json").string()).ok());
  CHECK_FALSE(m.last_error().empty());
  fs::remove_all(temp_dir());
}

TEST_CASE("a mesh opened without a mapping starts from the guess, unsaved", "[editor][rig]") {
  UndoStack undo;
  RigEditorModel m(undo);
  REQUIRE(m.open_mesh(scenes::source_path("assets/characters/dog.gltf"), (temp_dir() / "dog.rig.json").string()).ok());
  INFO(m.error());
  REQUIRE(m.character());
  CHECK(m.character()->rig->girdles.size() == 2);
  CHECK(m.mapping().tail.size() == 3);
  CHECK(m.dirty());
  CHECK_FALSE(m.notes().empty());  // the front legs were named as arms
  REQUIRE(m.save().ok());
  CHECK(fs::exists(temp_dir() / "dog.rig.json"));
  fs::remove_all(temp_dir());
}

TEST_CASE("the rig preview stands, then walks with its feet on the ground", "[editor][rig]") {
  UndoStack undo;
  RigEditorModel m(undo);
  REQUIRE(m.open_mapping(humanoid()).ok());
  REQUIRE(m.preview());
  const float x0 = m.preview()->x();
  for (int i = 0; i < 60; ++i) m.step_preview(1.0f / 60.0f);
  CHECK(m.preview()->x() == x0);  // standing
  m.preview_stick = 0.5f;
  for (int i = 0; i < 120; ++i) m.step_preview(1.0f / 60.0f);
  CHECK(m.preview()->x() > x0 + 2.0f);  // two seconds at about 2 m/s
  for (int i = 0; i < m.preview()->leg_count(); ++i) CHECK(m.preview()->foot_ws(i).y < 0.6f);
  // An edit restarts it.
  m.set_side(true, 0, Side::kFar);
  REQUIRE(m.preview());
  CHECK(m.preview()->x() == Approx(0.0f).margin(1e-6));
}
