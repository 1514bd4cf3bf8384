// ImGui smoke test under SDL's offscreen driver: the EditorSuite's windows are drawn for real
// (OpenGL3 backend on an offscreen Window) and driven through ImGuiIO's mouse fields — Debian's
// ImGui 1.86 has no event API — to drag a level box in the viewport and a spline key on the
// canvas. Set OSSA_EDITOR_SHOTS=<folder> to also write screenshots of every editor.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include "ossa/editor/editor_suite.h"
#include "ossa/game/world.h"
#include "ossa/platform/window.h"
#include "ossa/render/capture.h"
#include "ossa/render/debug_draw.h"
#include "ossa/render/gl.h"
#include "ossa/render/renderer.h"
#include "ossa/skeleton/pose.h"
#include "shared/scenes.h"

namespace ossa {
namespace {

constexpr int kW = 1280, kH = 720;

Level test_level() {
  return Level({Box::from_corner(-5.0f, -1.0f, 40.0f, 1.0f), Box::from_corner(5.0f, 0.0f, 2.0f, 0.3f),
                Box::from_corner(7.0f, 0.0f, 2.0f, 0.6f), Box::from_corner(9.0f, 0.0f, 3.0f, 0.9f)},
               glm::vec2(0.0f, 0.0f), "smoke");
}

// One GL context, ImGui context and renderer per process.
struct Gui {
  Window window;
  std::unique_ptr<Renderer> renderer;
  std::string error;
  Gui() {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    WindowDesc desc;
    desc.width = kW;
    desc.height = kH;
    desc.offscreen = true;
    auto w = Window::create(desc);
    if (!w.ok()) {
      error = w.message();
      return;
    }
    window = std::move(w.value());
    auto r = Renderer::create(scenes::source_path("shaders"));
    if (!r.ok()) {
      error = r.message();
      return;
    }
    renderer = std::make_unique<Renderer>(std::move(r.value()));
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    if (!ImGui_ImplOpenGL3_Init("#version 330")) error = "ImGui_ImplOpenGL3_Init failed";
  }
};

Gui& gui() {
  static Gui g;
  INFO(g.error);
  REQUIRE(g.error.empty());
  return g;
}

// A world with a walking quadruped, the suite over it and a frame driver.
struct Scene {
  World world{test_level(), SplinePrototypes::defaults()};
  std::unique_ptr<EditorSuite> suite;
  Camera2D camera;
  Controls controls;
  Scene() {
    world.spawn_player(std::make_shared<const Creature>(scenes::quadruped()), {1.0f, 1.0f});
    EditorPaths paths;
    paths.levels_dir = scenes::source_path("levels");
    paths.rig_file = scenes::source_path("assets/characters/humanoid.rig.json");
    paths.characters = {scenes::source_path("assets/characters/dog.rig.json"), paths.rig_file};
    suite = std::make_unique<EditorSuite>(world, &scenes::generator(), paths);
    camera.center_ws = {7.0f, 2.0f};
    camera.half_height = 3.5f;
    camera.aspect = static_cast<float>(kW) / kH;
    controls.move_x = 0.3f;
  }

  // One frame: world ticks, ImGui input from the given mouse, UI, scene and ImGui drawn.
  void frame(glm::vec2 mouse_px, bool down, const std::string& shot = {}) {
    Gui& g = gui();
    for (int i = 0; i < 2; ++i) world.step(controls);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(kW, kH);
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(mouse_px.x, mouse_px.y);
    io.MouseDown[0] = down;
    suite->update(io.DeltaTime);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    suite->handle_mouse(mouse_px, down, 0.0f, camera, {kW, kH});
    suite->draw_ui();
    ImGui::Render();
    if (shot.empty()) return;
    g.renderer->camera = camera;
    g.renderer->begin_frame(kW, kH, {0.55f, 0.70f, 0.85f});
    DebugDraw dd;
    dd.add_level(world.level(), {0.35f, 0.30f, 0.25f, 1.0f}, {0.15f, 0.12f, 0.1f, 1.0f});
    // The player's bones as lines (the sprite batch is the game's business).
    if (const Player* p = world.player()) {
      const auto& m = p->animator().world_matrices();
      const Skeleton& sk = p->skeleton();
      for (int b = 0; b < sk.bone_count(); ++b)
        dd.add_line(bone_start(m[b]), bone_end(m[b], sk.length(b)), {0.95f, 0.93f, 0.85f, 1.0f});
    }
    suite->draw_viewport(dd);
    g.renderer->draw_debug(dd);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    const char* dir = std::getenv("OSSA_EDITOR_SHOTS");
    if (dir && *dir) {
      std::filesystem::create_directories(dir);
      REQUIRE(write_png(std::string(dir) + "/" + shot + ".png", read_framebuffer(kW, kH)).ok());
    }
  }
  glm::vec2 px(glm::vec2 p_ws) const { return camera.world_to_pixel(p_ws, kW, kH); }
};

TEST_CASE("imgui smoke: drag a level box in the viewport, undo restores it", "[editor][imgui]") {
  Scene s;
  const Box before = s.world.level().box(2);
  const glm::vec2 start = s.px(before.center());
  s.frame(start, false);
  s.frame(start, false);
  REQUIRE_FALSE(ImGui::GetIO().WantCaptureMouse);  // the box is in the free viewport
  s.frame(start, true);                            // press
  REQUIRE(s.suite->level_editor().selected() == 2);
  for (int i = 1; i <= 8; ++i) s.frame(start + glm::vec2(10.0f * i, -5.0f * i), true);
  s.frame(start + glm::vec2(80.0f, -40.0f), false);  // release
  const Box after = s.world.level().box(2);
  REQUIRE(after.min_ws.x > before.min_ws.x + 0.5f);
  REQUIRE(after.min_ws.y > before.min_ws.y + 0.2f);
  REQUIRE(after.size() == before.size());
  REQUIRE(s.suite->undo().size() == 1);  // the whole drag is one step
  REQUIRE(s.suite->has_unsaved_changes());
  REQUIRE_FALSE(s.suite->request_quit());  // unsaved: asks first
  s.suite->undo().undo();
  REQUIRE(s.world.level().box(2) == before);
  REQUIRE_FALSE(s.suite->has_unsaved_changes());
  REQUIRE(s.suite->request_quit());
  // Switched off, the editors leave the mouse to the game.
  s.suite->enabled = false;
  s.frame(start, false);
  s.frame(start, true);
  s.frame(start + glm::vec2(50.0f, 0.0f), true);
  s.frame(start + glm::vec2(50.0f, 0.0f), false);
  REQUIRE(s.world.level().box(2) == before);
  REQUIRE(s.suite->undo().size() == 1);
}

TEST_CASE("imgui smoke: drag a spline key on the canvas, undo restores it", "[editor][imgui]") {
  Scene s;
  SplineEditorModel& m = s.suite->spline_editor();
  m.pick(PrototypeId::kLegSwingY);
  s.frame({2.0f, 700.0f}, false);
  s.frame({2.0f, 700.0f}, false);
  const auto key_px = s.suite->spline_key_screen_px(SplineVersion::kWalk, 1);
  REQUIRE(key_px);
  const HermiteKey before = m.spline(SplineVersion::kWalk).keys[1];
  const SplinePrototypes world_before = s.world.prototypes();
  s.frame(*key_px, false);
  s.frame(*key_px, true);  // press on the key
  REQUIRE(m.dragging());
  for (int i = 1; i <= 6; ++i) s.frame(*key_px + glm::vec2(0.0f, -6.0f * i), true);
  s.frame(*key_px + glm::vec2(0.0f, -36.0f), false);
  REQUIRE_FALSE(m.dragging());
  const HermiteKey after = m.spline(SplineVersion::kWalk).keys[1];
  REQUIRE(after.p > before.p + 0.01f);  // dragged up
  REQUIRE(after.t == Approx(before.t).margin(0.01));
  // The world's prototypes changed with it (the walking creature uses them).
  REQUIRE(s.world.prototypes()[PrototypeId::kLegSwingY].walk.keys[1].p == after.p);
  REQUIRE(s.suite->undo().size() == 1);
  REQUIRE(s.suite->undo().undo());
  REQUIRE(m.spline(SplineVersion::kWalk).keys[1].p == before.p);
  REQUIRE(s.world.prototypes()[PrototypeId::kLegSwingY].walk.keys[1].p ==
          world_before[PrototypeId::kLegSwingY].walk.keys[1].p);
}

TEST_CASE("imgui smoke: every window draws, with screenshots on request", "[editor][imgui]") {
  Scene s;
  s.suite->show_creature = true;
  s.suite->show_tuning = true;
  // Let the creature walk so the footfall diagram fills, with a box selected in the viewport.
  const glm::vec2 box_px = s.px(s.world.level().box(1).center());
  for (int i = 0; i < 40; ++i) s.frame({640.0f, 700.0f}, false);
  s.suite->show_creature = false;
  s.suite->show_tuning = false;
  s.frame(box_px, false);
  s.frame(box_px, true);
  s.frame(box_px, false);
  REQUIRE(s.suite->level_editor().selected() == 1);
  s.frame(box_px, false, "level_and_splines");
  s.suite->show_level = false;
  s.suite->show_splines = false;
  s.suite->show_tuning = true;
  for (int i = 0; i < 200; ++i) s.frame({640.0f, 700.0f}, false);
  REQUIRE(s.suite->tuning().leg_count() == 4);
  s.frame({640.0f, 700.0f}, false, "tuning");
  s.suite->show_tuning = false;
  s.suite->show_creature = true;
  s.frame({640.0f, 700.0f}, false, "creature");
  // A dirty document and a load request show the confirmation popup.
  s.suite->show_creature = false;
  s.suite->show_level = true;
  s.suite->level_editor().add_box({2.0f, 2.0f}, {1.0f, 0.5f});
  bool loaded = false;
  s.suite->confirm_discard(EditorDocument::kLevel, [&] { loaded = true; });
  REQUIRE_FALSE(loaded);
  s.frame({640.0f, 700.0f}, false);
  s.frame({640.0f, 700.0f}, false, "discard_popup");
  REQUIRE(ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel));
}

TEST_CASE("imgui smoke: a level drawn with its art shows its boxes' outlines while editing", "[editor][imgui]") {
  Scene s;
  s.frame({640.0f, 700.0f}, false);
  DebugDraw plain;
  s.suite->draw_viewport(plain);
  auto art = std::make_shared<LevelArt>();
  ArtLayer layer;
  layer.kind = ArtLayer::Kind::kImage;
  art->layers.push_back(layer);
  s.world.level().art = art;
  DebugDraw with_art;
  s.suite->draw_viewport(with_art);
  std::vector<int> in_view;
  s.world.level().overlapping(s.camera.visible_box(), in_view);
  REQUIRE_FALSE(in_view.empty());
  CHECK(with_art.lines().size() == plain.lines().size() + 8 * in_view.size());  // 4 lines of 2 vertices each
}

TEST_CASE("imgui smoke: the rig window shows the character walking, edits undo, apply makes the player it", "[editor][imgui]") {
  Scene s;
  s.suite->show_level = false;
  s.suite->show_splines = false;
  s.suite->show_rig = true;
  RigEditorModel& rig = s.suite->rig();
  REQUIRE(rig.is_open());
  REQUIRE(rig.character());
  rig.preview_stick = 0.5f;
  for (int i = 0; i < 60; ++i) s.frame({640.0f, 700.0f}, false);
  CHECK(rig.preview()->x() > 1.0f);
  // The preview draws the skinned mesh with its texture: triangles from that texture, as many
  // as the mesh has.
  const unsigned texture = s.suite->rig_preview_texture();
  REQUIRE(texture != 0u);
  unsigned textured_indices = 0;
  const ImDrawData* draw = ImGui::GetDrawData();
  for (int l = 0; l < draw->CmdListsCount; ++l) {
    for (const ImDrawCmd& cmd : draw->CmdLists[l]->CmdBuffer) {
      if (cmd.TextureId == reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture))) textured_indices += cmd.ElemCount;
    }
  }
  CHECK(textured_indices >= 3u * 20u);
  rig.select({RigSlotKind::kLegFoot, 0});
  s.frame({640.0f, 700.0f}, false, "rig");
  rig.clear({RigSlotKind::kLegFoot, 0});
  s.frame({640.0f, 700.0f}, false, "rig_error");
  CHECK_FALSE(rig.character());
  CHECK(s.suite->has_unsaved_changes());
  REQUIRE(s.suite->undo().undo());
  CHECK(rig.character());
  CHECK_FALSE(s.suite->has_unsaved_changes());
  // The creature panel (and the rig window) make the player a character.
  s.suite->show_creature = true;
  s.frame({640.0f, 700.0f}, false, "creature_characters");
  REQUIRE(s.suite->apply_character_to_player_for_tests(scenes::source_path("assets/characters/dog.rig.json")).ok());
  REQUIRE(s.world.player()->is_character());
  CHECK(s.world.player()->name() == "dog");
  for (int i = 0; i < 10; ++i) s.frame({640.0f, 700.0f}, false);
}

}  // namespace
}  // namespace ossa
