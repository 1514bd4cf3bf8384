// The playable game under SDL's offscreen driver: a virtual gamepad and pushed keyboard
// events drive the player, unplugging keeps the game alive, replays play back to the same
// state, and the `ossa` binary renders the creature on the level and rejects bad arguments.

#include <catch2/catch.hpp>

#include <SDL.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/camera_follow.h"
#include "app/game.h"
#include "app/game_editors.h"
#include "app/options.h"
#include "ossa/io/json.h"
#include "ossa/anim/animator.h"
#include "ossa/gen/skeleton_builder.h"
#include "shared/scenes.h"
#include "ossa/level/level_load.h"
#include "ossa/platform/image.h"
#include "ossa/platform/input.h"
#include "ossa/render/renderer.h"

namespace {

using namespace ossa;

constexpr double kFrame = 1.0 / 60.0;

void use_offscreen() { setenv("SDL_VIDEODRIVER", "offscreen", 1); }

std::string temp_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("ossa_app_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}

GameOptions quiet_options() {
  GameOptions o;
  o.headless = true;
  o.npcs = 0;
  o.width = 320;
  o.height = 180;
  o.out_dir = temp_dir();
  o.level = resolve_data_path("levels/default.json");
  return o;
}

void run_frames(Game& game, int n) {
  for (int i = 0; i < n; ++i) REQUIRE(game.frame(kFrame));
}

void push_key(SDL_Scancode code, bool down, Uint16 mod = KMOD_NONE) {
  SDL_Event e{};
  e.key.keysym.mod = mod;
  e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
  e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
  e.key.keysym.scancode = code;
  e.key.keysym.sym = SDL_GetKeyFromScancode(code);
  REQUIRE(SDL_PushEvent(&e) == 1);
}

int attach_virtual_pad() {
  const int index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, 6, 15, 0);
  REQUIRE(index >= 0);
  return index;
}

std::string bin_dir() {
  // CTest sets OSSA_BIN_DIR; run by hand, `ossa` sits next to this test executable.
  const char* d = std::getenv("OSSA_BIN_DIR");
  if (d && *d) return d;
  std::error_code ec;
  return std::filesystem::read_symlink("/proc/self/exe", ec).parent_path().string();
}

// Runs a command with stderr to a file; returns the exit status and the message.
int run_command(const std::string& cmd, std::string* err) {
  const std::string err_file = temp_dir() + "/stderr.txt";
  const int rc = std::system((cmd + " >/dev/null 2>" + err_file).c_str());
  std::ifstream f(err_file);
  std::stringstream ss;
  ss << f.rdbuf();
  if (err) *err = ss.str();
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

TEST_CASE("radial dead zone: zero inside, the stick itself outside, never beyond 1", "[app]") {
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const glm::vec2 s{u(rng), u(rng)};
    const float dz = 0.5f * (u(rng) + 1.0f) * 0.4f;
    const glm::vec2 out = radial_dead_zone(s, dz);
    const float m = std::hypot(s.x, s.y);
    if (m <= dz) {
      CHECK(out == glm::vec2(0.0f));
    } else if (m <= 1.0f) {
      CHECK(out == s);
    } else {
      CHECK(std::hypot(out.x, out.y) == Approx(1.0f));
      CHECK(out.x * s.x >= 0.0f);  // direction kept
      CHECK(out.y * s.y >= 0.0f);
    }
  }
  CHECK(radial_dead_zone({1.0f, 0.0f}, 0.15f).x == 1.0f);
  CHECK(radial_dead_zone({0.5f, 0.0f}, 0.15f).x == 0.5f);
  CHECK(radial_dead_zone({0.1f, 0.1f}, 0.15f) == glm::vec2(0.0f));
}

TEST_CASE("a virtual gamepad drives the player: half stick walks, full stick runs", "[app]") {
  use_offscreen();
  Game game;
  REQUIRE(game.init(quiet_options()).ok());
  const int index = attach_virtual_pad();
  SDL_Joystick* joy = SDL_JoystickOpen(index);
  REQUIRE(joy != nullptr);
  run_frames(game, 2);
  REQUIRE(game.gamepad().connected());

  const Animator& a = game.world().player()->animator();
  const float x0 = a.x();
  REQUIRE(SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_LEFTX, 16384) == 0);
  run_frames(game, 180);  // 3 s
  CHECK(game.last_controls().move_x == Approx(0.5f).epsilon(0.001));
  CHECK(a.gait() == Gait::kWalk);
  CHECK(a.velocity() == Approx(a.walk_speed()).epsilon(0.05));
  CHECK(a.x() > x0 + 1.0f);

  REQUIRE(SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_LEFTX, 32767) == 0);
  run_frames(game, 240);  // 4 s
  CHECK(game.last_controls().move_x == Approx(1.0f));
  CHECK(a.gait() != Gait::kWalk);
  CHECK(a.gait() != Gait::kIdle);
  CHECK(a.velocity() == Approx(a.run_speed()).epsilon(0.05));

  // Left, half throw: walks left.
  REQUIRE(SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_LEFTX, -16384) == 0);
  run_frames(game, 240);
  CHECK(a.velocity() < -0.6f * a.walk_speed());
  CHECK(a.facing() == -1);

  // A jumps: one jump per press, however long it is held.
  REQUIRE(SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_LEFTX, 0) == 0);
  run_frames(game, 120);
  const int jumps = a.locomotion_stats().jumps;
  REQUIRE(SDL_JoystickSetVirtualButton(joy, SDL_CONTROLLER_BUTTON_A, 1) == 0);
  run_frames(game, 3);
  CHECK(game.last_controls().jump);
  run_frames(game, 177);
  REQUIRE(SDL_JoystickSetVirtualButton(joy, SDL_CONTROLLER_BUTTON_A, 0) == 0);
  run_frames(game, 60);
  CHECK(a.locomotion_stats().jumps == jumps + 1);
  CHECK(a.locomotion() == Locomotion::kGrounded);

  SDL_JoystickClose(joy);
  SDL_JoystickDetachVirtual(index);
  run_frames(game, 2);
}

TEST_CASE("keyboard events pushed through SDL walk and run the player", "[app]") {
  use_offscreen();
  Game game;
  REQUIRE(game.init(quiet_options()).ok());
  const Animator& a = game.world().player()->animator();
  const float x0 = a.x();
  push_key(SDL_SCANCODE_D, true);
  run_frames(game, 180);
  CHECK(game.last_controls().move_x == 0.5f);
  CHECK_FALSE(game.last_controls().run);
  CHECK(a.velocity() == Approx(a.walk_speed()).epsilon(0.05));
  CHECK(a.gait() == Gait::kWalk);
  CHECK(a.x() > x0 + 2.0f);

  push_key(SDL_SCANCODE_LSHIFT, true);
  run_frames(game, 240);
  CHECK(game.last_controls().move_x == 1.0f);
  CHECK(game.last_controls().run);
  CHECK(a.velocity() == Approx(a.run_speed()).epsilon(0.05));

  push_key(SDL_SCANCODE_LSHIFT, false);
  push_key(SDL_SCANCODE_D, false);
  run_frames(game, 240);
  CHECK(game.last_controls().move_x == 0.0f);
  CHECK(std::abs(a.velocity()) < 0.05f);

  push_key(SDL_SCANCODE_LEFT, true);
  run_frames(game, 120);
  CHECK(a.velocity() < 0.0f);
  push_key(SDL_SCANCODE_LEFT, false);

  // Space, W and Up each jump once per press; the creature lands again.
  for (SDL_Scancode key : {SDL_SCANCODE_SPACE, SDL_SCANCODE_W, SDL_SCANCODE_UP}) {
    run_frames(game, 60);
    const int jumps = a.locomotion_stats().jumps;
    push_key(key, true);
    run_frames(game, 2);
    CHECK(game.last_controls().jump);
    run_frames(game, 118);
    push_key(key, false);
    run_frames(game, 60);
    CHECK(a.locomotion_stats().jumps == jumps + 1);
    CHECK(a.locomotion() == Locomotion::kGrounded);
  }

  // H cycles the HUD: player (the default), developer, off, player.
  CHECK(game.hud_mode() == HudMode::kPlayer);
  for (HudMode want : {HudMode::kDeveloper, HudMode::kOff, HudMode::kPlayer}) {
    push_key(SDL_SCANCODE_H, true);
    push_key(SDL_SCANCODE_H, false);
    run_frames(game, 1);
    CHECK(game.hud_mode() == want);
  }

  // Escape quits.
  push_key(SDL_SCANCODE_ESCAPE, true);
  CHECK_FALSE(game.frame(kFrame));
}

TEST_CASE("F2 pressed and released within one frame shows and hides the editors, Ctrl+Z, Ctrl+Y and Ctrl+S too",
          "[app]") {
  use_offscreen();
  GameOptions o = quiet_options();
  // A copy of the default level: Ctrl+S writes it.
  o.level = temp_dir() + "/keys_level.json";
  std::filesystem::copy_file(resolve_data_path("levels/default.json"), o.level,
                             std::filesystem::copy_options::overwrite_existing);
  Game game;
  REQUIRE(game.init(o).ok());
  GameEditors editors(game, o);
  EditorSuite& suite = editors.suite();
  suite.enabled = false;
  run_frames(game, 2);
  // Four taps, each a press and its release in the same frame's events (ImGui 1.86's key
  // state drops these): open, close, open, close.
  CHECK(game.hud_shown());
  for (int tap = 0; tap < 4; ++tap) {
    push_key(SDL_SCANCODE_F2, true);
    push_key(SDL_SCANCODE_F2, false);
    run_frames(game, 1);
    INFO("tap " << tap);
    CHECK(suite.enabled == (tap % 2 == 0));
    CHECK(game.hud_shown() == !suite.enabled);  // the HUD is hidden while the editors are shown
  }
  REQUIRE_FALSE(suite.enabled);

  // Editors shown: a box added, Ctrl+Z tapped within a frame removes it, Ctrl+Y brings it back.
  push_key(SDL_SCANCODE_F2, true);
  push_key(SDL_SCANCODE_F2, false);
  run_frames(game, 1);
  REQUIRE(suite.enabled);
  const size_t boxes = game.world().level().colliders().size();
  suite.level_editor().add_box({2.0f, 6.0f}, {1.0f, 1.0f});
  REQUIRE(game.world().level().colliders().size() == boxes + 1);
  const auto tap_ctrl = [&](SDL_Scancode key) {
    push_key(SDL_SCANCODE_LCTRL, true, KMOD_LCTRL);
    push_key(key, true, KMOD_LCTRL);
    push_key(key, false, KMOD_LCTRL);
    push_key(SDL_SCANCODE_LCTRL, false);
    run_frames(game, 1);
  };
  tap_ctrl(SDL_SCANCODE_Z);
  CHECK(game.world().level().colliders().size() == boxes);
  tap_ctrl(SDL_SCANCODE_Y);
  CHECK(game.world().level().colliders().size() == boxes + 1);
  // Ctrl+S saves the level to its file.
  CHECK(suite.level_editor().dirty());
  tap_ctrl(SDL_SCANCODE_S);
  CHECK_FALSE(suite.level_editor().dirty());
  auto saved = load_level(o.level, LevelLoadOptions{});
  REQUIRE(saved.ok());
  CHECK(saved->colliders().size() == boxes + 1);
}

TEST_CASE("the camera frames every example at its true size: small ones fill the view, long ones fit in it", "[app]") {
  // For each example animal at its true size (hip 3 cm to 3.5 m, length 4 cm to 27 m) in a
  // 16:9 view: the body's length within two thirds of the width, and the creature's height
  // (its hip) at least a tenth of the view's height (a frog is not a few pixels) where its
  // length does not need the room.
  const float aspect = 16.0f / 9.0f;
  for (const Animal& animal : scenes::generator().dataset().animals) {
    const std::string& name = animal.name;
    const Creature c = build_creature(scenes::generator().example(name).value()).value();
    const Animator a(c, SplinePrototypes::defaults());
    const float hip = a.hip_height(), length = a.rig().scale.length;
    const float hh = framing_half_height(hip, length, aspect);
    INFO(name << ": hip " << hip << " m, length " << length << " m, half height " << hh << " m");
    const float width = 2.0f * hh * aspect;
    CHECK(length <= (2.0f / 3.0f) * width + 1e-4f);
    // Unless its length takes the room (the whales, the snake, the trout): a tenth or more.
    if (length < 0.99f * (2.0f / 3.0f) * width) CHECK(hip >= 0.099f * 2.0f * hh);
  }
  // A 27 m whale lies within two thirds of the width, a 3 cm frog stands a fifth of the height.
  CHECK(framing_half_height(1.0f, 27.0f, aspect) * 2.0f * aspect * (2.0f / 3.0f) == Approx(27.0f));
  CHECK(framing_half_height(0.03f, 0.04f, aspect) == Approx(0.15f));
}

TEST_CASE("the camera shows the landing of every ledge of drops.json 0.3 s before touch-down and rests still",
          "[app]") {
  use_offscreen();
  for (const bool run : {false, true}) {
    INFO((run ? "running" : "walking"));
    GameOptions o = quiet_options();
    o.level = resolve_data_path("levels/drops.json");
    Game game;
    REQUIRE(game.init(o).ok());
    const Animator& a = game.world().player()->animator();
    const Level& level = game.world().level();
    struct Sample {
      double t;
      Box view;
      bool airborne;
      float x, feet;
    };
    std::vector<Sample> samples;
    push_key(SDL_SCANCODE_D, true);
    if (run) push_key(SDL_SCANCODE_LSHIFT, true, KMOD_LSHIFT);
    double t = 0.0;
    // Over the 0.3, 1, 2 and 4 m ledges (x = 6, 12, 18, 26) to the gap at x = 38.
    while (a.x() < 36.5f && t < 60.0) {
      REQUIRE(game.frame(kFrame));
      t += kFrame;
      samples.push_back({t, game.camera().visible_box(), a.airborne(), a.x(), a.root_y() - a.hip_height()});
    }
    REQUIRE(a.x() >= 36.5f);
    if (run) push_key(SDL_SCANCODE_LSHIFT, false);
    push_key(SDL_SCANCODE_D, false);
    // The ledges: a box's right edge where the next box starts lower.
    struct Ledge {
      float x, upper, lower;
    };
    std::vector<Ledge> ledges;
    for (const Box& b : level.colliders()) {
      for (const Box& c : level.colliders()) {
        if (std::abs(c.min_ws.x - b.max_ws.x) < 1e-3f && c.max_ws.y < b.max_ws.y - 0.2f && b.max_ws.x > level.spawn_ws.x &&
            b.max_ws.x < 36.5f) {
          ledges.push_back({b.max_ws.x, b.max_ws.y, c.max_ws.y});
        }
      }
    }
    REQUIRE(ledges.size() == 4);
    bool fell_in_the_air = false;
    for (const Ledge& ledge : ledges) {
      // Touch-down: the first frame past the edge with the feet down on the lower box.
      size_t i = 0;
      while (i < samples.size() && !(samples[i].x > ledge.x && samples[i].feet < ledge.lower + 0.1f)) ++i;
      REQUIRE(i < samples.size());
      for (size_t j = i; j > 0 && samples[j - 1].x > ledge.x - 1.0f; --j) fell_in_the_air |= samples[j - 1].airborne;
      const glm::vec2 landing{samples[i].x, ledge.lower};
      for (size_t j = i + 1; j-- > 0 && samples[j].t >= samples[i].t - 0.3 - 1e-9;) {
        INFO("ledge at x " << ledge.x << ", " << ledge.upper - ledge.lower << " m: landing at (" << landing.x << ", "
                           << landing.y << ") at t = " << samples[i].t << " s; frame at t = " << samples[j].t
                           << " s, view y " << samples[j].view.min_ws.y << " .. " << samples[j].view.max_ws.y << ", x "
                           << samples[j].view.min_ws.x << " .. " << samples[j].view.max_ws.x);
        const Box& v = samples[j].view;
        CHECK(landing.x > v.min_ws.x + 0.05f);
        CHECK(landing.x < v.max_ws.x - 0.05f);
        CHECK(landing.y > v.min_ws.y + 0.05f);
        CHECK(landing.y < v.max_ws.y - 0.05f);
      }
    }
    CHECK(fell_in_the_air);  // the 4 m ledge at least is a fall

    // At rest the camera comes to a stop: no jitter.
    run_frames(game, 240);
    glm::vec2 last = game.camera().center_ws;
    float moved = 0.0f;
    for (int i = 0; i < 60; ++i) {
      run_frames(game, 1);
      moved = std::max(moved, glm::length(game.camera().center_ws - last));
      last = game.camera().center_ws;
    }
    CHECK(moved < 5e-4f);
  }
}

TEST_CASE("unplugging the gamepad mid-game keeps running and hands control to the keyboard", "[app]") {
  use_offscreen();
  Game game;
  REQUIRE(game.init(quiet_options()).ok());
  const int index = attach_virtual_pad();
  SDL_Joystick* joy = SDL_JoystickOpen(index);
  REQUIRE(joy != nullptr);
  run_frames(game, 2);
  REQUIRE(game.gamepad().connected());
  REQUIRE(SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_LEFTX, 32767) == 0);
  run_frames(game, 60);
  CHECK(game.world().player()->animator().velocity() > 0.5f);

  SDL_JoystickClose(joy);
  REQUIRE(SDL_JoystickDetachVirtual(index) == 0);
  run_frames(game, 120);  // no crash, no stale stick
  CHECK_FALSE(game.gamepad().connected());
  CHECK(game.last_controls().move_x == 0.0f);
  CHECK(std::abs(game.world().player()->animator().velocity()) < 0.05f);

  const float x0 = game.world().player()->animator().x();
  push_key(SDL_SCANCODE_D, true);
  run_frames(game, 120);
  CHECK(game.last_controls().move_x == 0.5f);
  CHECK(game.world().player()->animator().x() > x0 + 1.0f);
  push_key(SDL_SCANCODE_D, false);

  // Plug a new one in: it is picked up again.
  const int again = attach_virtual_pad();
  run_frames(game, 2);
  CHECK(game.gamepad().connected());
  SDL_JoystickDetachVirtual(again);
  run_frames(game, 2);
  CHECK_FALSE(game.gamepad().connected());
}

TEST_CASE("a recorded replay plays back to the same player state", "[app]") {
  use_offscreen();
  const std::string replay = temp_dir() + "/demo.replay.json";
  float x_recorded = 0.0f;
  uint64_t hash_recorded = 0;
  uint64_t ticks_recorded = 0;
  {
    GameOptions o = quiet_options();
    o.demo = true;
    o.npcs = 2;
    o.record = replay;
    Game game;
    REQUIRE(game.init(o).ok());
    run_frames(game, 600);  // 10 s: walk, run, stop, walk, jump, walk
    REQUIRE(game.finish().ok());
    REQUIRE(game.world().player()->animator().locomotion_stats().jumps == 1);
    x_recorded = game.world().player()->animator().x();
    hash_recorded = pose_hash(game.world().player()->animator().world_matrices());
    ticks_recorded = game.world().tick();
  }
  REQUIRE(std::filesystem::exists(replay));
  GameOptions o = quiet_options();
  o.replay = replay;
  o.level.clear();  // the replay's level
  Game game;
  REQUIRE(game.init(o).ok());
  int frames = 0;
  while (game.frame(kFrame) && frames < 10000) ++frames;
  CHECK(game.replay_finished());
  CHECK(game.world().tick() == ticks_recorded);
  CHECK(game.world().player()->animator().x() == x_recorded);
  CHECK(pose_hash(game.world().player()->animator().world_matrices()) == hash_recorded);
  CHECK(x_recorded > game.world().level().spawn_ws.x + 3.0f);
}

TEST_CASE("creatures cycle through the examples and random ones build", "[app]") {
  use_offscreen();
  Game game;
  REQUIRE(game.init(quiet_options()).ok());
  CHECK(game.creature_name() == kDefaultExample);
  game.next_example();
  const std::string second = game.creature_name();
  CHECK(second != kDefaultExample);
  run_frames(game, 10);
  game.random_creature();
  run_frames(game, 10);
  CHECK(game.creature_name() != second);
}

TEST_CASE("a rigged character plays, cycles with C, walks among character NPCs and replays", "[app]") {
  use_offscreen();
  const std::string replay = temp_dir() + "/character.replay.json";
  float x_recorded = 0.0f;
  uint64_t hash_recorded = 0;
  {
    GameOptions o = quiet_options();
    o.character = "assets/characters/humanoid.rig.json";
    o.demo = true;
    o.npcs = 2;
    o.npc_characters = true;
    o.record = replay;
    Game game;
    const Status s = game.init(o);
    INFO((s.ok() ? std::string() : s.message()));
    REQUIRE(s.ok());
    CHECK(game.creature_name() == "humanoid");
    REQUIRE(game.world().player()->is_character());
    CHECK_FALSE(game.world().npc(0).is_character());
    CHECK(game.world().npc(1).is_character());  // every other NPC is a shipped character
    run_frames(game, 300);
    REQUIRE(game.finish().ok());
    x_recorded = game.world().player()->animator().x();
    hash_recorded = pose_hash(game.world().player()->animator().world_matrices());
    CHECK(x_recorded > game.world().level().spawn_ws.x + 3.0f);
  }
  auto doc = read_json_file(replay);
  REQUIRE(doc.ok());
  CHECK(doc.value()["character"] == "assets/characters/humanoid.rig.json");  // which character was played
  CHECK_FALSE(doc.value().contains("creature"));
  {
    GameOptions o = quiet_options();
    o.replay = replay;
    o.level.clear();
    Game game;
    REQUIRE(game.init(o).ok());
    int frames = 0;
    while (game.frame(kFrame) && frames < 10000) ++frames;
    CHECK(game.creature_name() == "humanoid");
    CHECK(game.world().player()->animator().x() == x_recorded);
    CHECK(pose_hash(game.world().player()->animator().world_matrices()) == hash_recorded);
  }
  // C cycles the shipped characters in the README's order (humanoid, dog); N goes back to the
  // examples.
  Game game;
  REQUIRE(game.init(quiet_options()).ok());
  push_key(SDL_SCANCODE_C, true);
  push_key(SDL_SCANCODE_C, false);
  run_frames(game, 5);
  CHECK(game.creature_name() == "humanoid");
  CHECK(game.world().player()->is_character());
  game.next_character();
  run_frames(game, 5);
  CHECK(game.creature_name() == "dog");
  game.next_character();
  run_frames(game, 5);
  CHECK(game.creature_name() == "humanoid");
  CHECK(game.set_player_character("assets/characters/dog.rig.json").ok());
  CHECK(game.creature_name() == "dog");
  const Status bad = game.set_player_character("tests/tools/data/missing_bone.rig.json");
  REQUIRE_FALSE(bad.ok());
  CHECK_THAT(bad.message(), Catch::Contains("legs[1].lower"));
  CHECK(game.creature_name() == "dog");  // kept
  game.next_example();
  run_frames(game, 5);
  CHECK_FALSE(game.world().player()->is_character());
}

TEST_CASE("ossa --headless --frames 600 --png shows the creature on the level", "[app]") {
  const std::string dir = temp_dir();
  const std::string png = dir + "/headless.png", state = dir + "/state.json";
  std::string err;
  // The bone sprites (--look bones): cream pixels are easy to tell from the level's colours.
  const int rc = run_command(bin_dir() + "/ossa --headless --frames 600 --no-hud --look bones --png " + png + " --state " + state, &err);
  INFO(err);
  REQUIRE(rc == 0);
  auto doc = read_json_file(state);
  REQUIRE(doc.ok());
  CHECK(doc.value()["frames"] == 600);
  CHECK(doc.value()["player"]["creature"] == "horse");
  CHECK(doc.value()["player"]["x"].get<double>() > doc.value()["spawn"]["x"].get<double>() + 5.0);
  CHECK(doc.value()["spawn"]["x"] == 2.0);

  auto image = load_image(png);
  REQUIRE(image.ok());
  const Image& img = image.value();
  REQUIRE(img.width == 1280);
  // Bone-coloured pixels (cream: bright, red above blue, unlike sky, hills, grass or earth)
  // in the middle of the frame, where the camera keeps the player, with earth below them.
  int bone_pixels = 0, grounded_columns = 0;
  for (int x = img.width / 5; x < img.width * 4 / 5; ++x) {
    int lowest_bone = -1;
    for (int y = 0; y < img.height; ++y) {
      const uint8_t* p = img.pixel(x, y);
      if (p[0] > 170 && p[1] > 150 && p[0] > p[2] + 20 && p[0] - p[1] < 40) {
        ++bone_pixels;
        lowest_bone = y;
      }
    }
    if (lowest_bone < 0) continue;
    for (int y = lowest_bone + 1; y < img.height; ++y) {
      const uint8_t* p = img.pixel(x, y);
      if (p[0] > 90 && p[0] < 150 && p[1] > 60 && p[1] < 110 && p[2] < 80) {  // earth brown
        ++grounded_columns;
        break;
      }
    }
  }
  CHECK(bone_pixels > 2000);
  CHECK(grounded_columns > 100);
}

TEST_CASE("ossa --headless draws bodies by default: the pig wears its pink coat on the ground", "[app]") {
  const std::string dir = temp_dir();
  const std::string png = dir + "/pig.png";
  std::string err;
  const int rc = run_command(bin_dir() + "/ossa --headless --frames 240 --no-hud --npcs 0 --example pig --png " + png, &err);
  INFO(err);
  REQUIRE(rc == 0);
  auto image = load_image(png);
  REQUIRE(image.ok());
  const Image& img = image.value();
  // Pink coat pixels (red well above green and blue, bright: no sky, hill, grass, earth or
  // bone sprite colour) in the middle of the frame, with earth below them.
  int coat = 0, grounded_columns = 0, bones = 0;
  for (int x = img.width / 5; x < img.width * 4 / 5; ++x) {
    int lowest = -1;
    for (int y = 0; y < img.height; ++y) {
      const uint8_t* p = img.pixel(x, y);
      if (p[0] > 150 && p[0] > p[1] + 25 && p[0] > p[2] + 30 && p[1] >= p[2] - 10) ++coat, lowest = y;
      bones += p[0] > 235 && p[1] > 225 && p[2] > 195;  // the sprites' ivory highlights
    }
    if (lowest < 0) continue;
    for (int y = lowest + 1; y < img.height; ++y) {
      const uint8_t* p = img.pixel(x, y);
      if (p[0] > 90 && p[0] < 150 && p[1] > 60 && p[1] < 110 && p[2] < 80) {
        ++grounded_columns;
        break;
      }
    }
  }
  CHECK(coat > 3000);
  CHECK(grounded_columns > 100);
  CHECK(bones < 50);  // the body look draws no bone sprites
}

TEST_CASE("a GIF leaves the HUD out: with and without the HUD the same frames", "[app]") {
  const std::string dir = temp_dir();
  std::string gifs[2];
  for (int hud = 0; hud < 2; ++hud) {
    gifs[hud] = dir + "/hud" + std::to_string(hud) + ".gif";
    std::string err;
    const int rc = run_command(bin_dir() + "/ossa --headless --frames 20 --npcs 0 --size 320x180 --gif " + gifs[hud] +
                                   (hud ? "" : " --no-hud"),
                               &err);
    INFO(err);
    REQUIRE(rc == 0);
  }
  std::ifstream a(gifs[0], std::ios::binary), b(gifs[1], std::ios::binary);
  const std::string bytes_a((std::istreambuf_iterator<char>(a)), {}), bytes_b((std::istreambuf_iterator<char>(b)), {});
  REQUIRE(bytes_a.size() > 100);
  CHECK(bytes_a == bytes_b);
  // The same run's last frame as PNG keeps the HUD (screenshots show what the window shows).
  std::string err;
  const std::string png[2] = {dir + "/hud0.png", dir + "/hud1.png"};
  for (int hud = 0; hud < 2; ++hud) {
    REQUIRE(run_command(bin_dir() + "/ossa --headless --frames 20 --npcs 0 --size 320x180 --png " + png[hud] +
                            (hud ? "" : " --no-hud"),
                        &err) == 0);
  }
  auto with = load_image(png[1]), without = load_image(png[0]);
  REQUIRE(with.ok());
  REQUIRE(without.ok());
  CHECK(with->rgba != without->rgba);
}

TEST_CASE("ossa-render --level draws the level: its look, its art, and its boxes when an image is missing", "[app]") {
  const std::string dir = temp_dir();
  const auto render = [&](const std::string& level, const std::string& png, std::string* err) {
    return run_command(bin_dir() + "/ossa-render --example horse --width 320 --height 180 --level " + level + " --png " + png, err);
  };
  std::string err;
  REQUIRE(render(resolve_data_path("levels/drops.json"), dir + "/drops.png", &err) == 0);
  REQUIRE(render(resolve_data_path("levels/stairs.json"), dir + "/stairs.png", &err) == 0);
  REQUIRE(render(resolve_data_path("tests/level/data/art/meadow.tmx"), dir + "/meadow.png", &err) == 0);
  CHECK(err.find("ossa render:") == std::string::npos);
  // The map without its images, next to its tilesets: warnings name the map and each image.
  const std::string bare = dir + "/bare";
  std::filesystem::create_directories(bare);
  for (const char* f : {"meadow.tmx", "meadow.tsx", "props.tsj"}) {
    std::filesystem::copy_file(resolve_data_path(std::string("tests/level/data/art/") + f), bare + "/" + f,
                               std::filesystem::copy_options::overwrite_existing);
  }
  REQUIRE(render(bare + "/meadow.tmx", dir + "/bare.png", &err) == 0);
  CHECK_THAT(err, Catch::Contains(bare + "/meadow.tmx: image " + bare + "/meadow.png"));
  CHECK_THAT(err, Catch::Contains("drawing the level's boxes"));
  auto drops = load_image(dir + "/drops.png"), stairs = load_image(dir + "/stairs.png");
  auto meadow = load_image(dir + "/meadow.png"), fallback = load_image(dir + "/bare.png");
  REQUIRE((drops.ok() && stairs.ok() && meadow.ok() && fallback.ok()));
  CHECK(drops->rgba != stairs->rgba);
  CHECK(meadow->rgba != fallback->rgba);
}

TEST_CASE("ossa rejects bad arguments and files with a message", "[app]") {
  const std::string ossa = bin_dir() + "/ossa";
  const std::string dir = temp_dir();
  {
    std::ofstream bad(dir + "/bad_level.json");
    bad << R"({"format": "ossa.level", "version": 1, "spawn": {"x": 0, "y": 0}, "colliders": [{"x": 0}]})";
  }
  const struct {
    std::string args, expect;
  } cases[] = {
      {"--frames abc --headless", "--frames"},
      {"--hz 1000 --headless", "--hz"},
      {"--npcs -1 --headless", "--npcs"},
      {"--threads -2 --headless", "--threads"},
      {"--bogus", "unknown argument"},
      {"--level", "missing value"},
      {"--headless --level /nonexistent/level.json", "nonexistent"},
      {"--headless --level " + dir + "/bad_level.json", "colliders"},
      {"--headless --example unicorn", "unicorn"},
      {"--headless --creature /nonexistent.creature.json", "nonexistent"},
      {"--headless --replay /nonexistent.replay.json", "nonexistent"},
      {"--headless --example horse --seed 3", "only one"},
      {"--headless --example horse --character assets/characters/dog.rig.json", "only one"},
      {"--headless --character /nonexistent.rig.json", "nonexistent"},
      {"--headless --character " + resolve_data_path("tests/tools/data/missing_bone.rig.json"), "legs[1].lower: bone \"knee_r\""},
      {"--headless --size 5x5", "--size"},
  };
  for (const auto& c : cases) {
    std::string err;
    const int rc = run_command(ossa + " " + c.args, &err);
    INFO(c.args << " -> " << err);
    CHECK(rc != 0);
    CHECK(err.find(c.expect) != std::string::npos);
    CHECK(err.find("ossa:") == 0);
  }
  std::string err;
  CHECK(run_command(ossa + " --help", &err) == 0);
}

TEST_CASE("command line parsing", "[app]") {
  auto p = parse_game_args({"--headless", "--example", "dromedary", "--npcs", "5", "--hz", "240", "--threads", "2"});
  REQUIRE(p.ok());
  CHECK(p->options.headless);
  CHECK(p->options.demo);
  CHECK(p->options.frames == 600);
  CHECK(p->options.example == "dromedary");
  CHECK(p->options.npcs == 5);
  CHECK(p->options.tick_hz == 240);
  CHECK(p->options.threads == 2);
  auto r = parse_game_args({"--headless", "--replay", "x.json"});
  REQUIRE(r.ok());
  CHECK_FALSE(r->options.demo);
  CHECK(r->options.frames == 0);
  CHECK_FALSE(parse_game_args({"--seed", "-3"}).ok());
  CHECK(parse_game_args({"--help"})->help);
  // Bodies by default; --look picks another, a wrong one names the flag and the choices.
  CHECK(p->options.look == CreatureLook::kBody);
  CHECK(parse_game_args({"--look", "xray"})->options.look == CreatureLook::kXray);
  CHECK(parse_game_args({"--look", "bones"})->options.look == CreatureLook::kBones);
  const auto bad = parse_game_args({"--look", "fur"});
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.message().find("--look: expected body, xray or bones") != std::string::npos);
}

TEST_CASE("a slow frame runs at most max_steps_per_frame ticks and drops the rest", "[app]") {
  use_offscreen();
  GameOptions o = quiet_options();
  o.max_steps_per_frame = 8;
  o.tick_hz = 240;
  Game game;
  REQUIRE(game.init(o).ok());
  uint64_t t0 = game.world().tick();
  REQUIRE(game.frame(0.2));  // 48 ticks due
  CHECK(game.world().tick() - t0 == 8);
  t0 = game.world().tick();
  REQUIRE(game.frame(1.0 / 60.0));  // the backlog was dropped: 4 ticks, not 44
  CHECK(game.world().tick() - t0 <= 5);
  CHECK(game.world().tick() - t0 >= 3);
  // Steady frames: ticks follow wall time exactly on average.
  t0 = game.world().tick();
  for (int i = 0; i < 120; ++i) REQUIRE(game.frame(1.0 / 60.0));
  CHECK(static_cast<double>(game.world().tick() - t0) == Approx(480.0).margin(1.0));
}

TEST_CASE("ossa --size: the creatures the game makes in a fixed frame, a genome file resized, WxH still the window", "[app]") {
  // Told apart by their form: true or a number is the creatures' size, WxH the window's.
  auto p = parse_game_args({"--size", "2", "--size", "320x180"});
  REQUIRE(p.ok());
  REQUIRE(p->options.size);
  CHECK_FALSE(p->options.size->true_size);
  CHECK(p->options.size->frame_m == 2.0f);
  CHECK(p->options.width == 320);
  CHECK(p->options.height == 180);
  CHECK(parse_game_args({"--size", "true"})->options.size->true_size);
  CHECK_FALSE(parse_game_args({"--example", "horse"})->options.size);  // unset: true size, files as saved
  const auto bad = parse_game_args({"--size", "big"});
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.message().find("--size: expected true or a frame in metres") != std::string::npos);
  CHECK_FALSE(parse_game_args({"--size", "0.01"}).ok());
  CHECK_FALSE(parse_game_args({"--size", "2", "--replay", "x.json"}).ok());

  use_offscreen();
  {
    GameOptions o = quiet_options();
    o.npcs = 1;
    o.size = SizeChoice{false, 2.0f};
    Game game;
    REQUIRE(game.init(o).ok());
    CHECK(game.world().player()->creature().scale == Approx(0.002f));
    game.next_example();  // N keeps the size
    CHECK(game.world().player()->creature().scale == Approx(0.002f));
    game.random_creature();  // M too
    CHECK(game.world().player()->creature().scale == Approx(0.002f));
  }

  // A genome file (the horse at its true size) is resized by --size, and kept as saved without
  // it. One game at a time (each has its window and ImGui context).
  const std::string file = temp_dir() + "/true_horse.creature.json";
  auto generator = Generator::load(resolve_data_path("assets/creatures/examples.json"), ossa::body_volume_m3);
  REQUIRE(generator.ok());
  auto horse = generator->example("horse");
  REQUIRE(horse.ok());
  REQUIRE(horse->scale > 0.0022f);
  REQUIRE(save_genome(file, *horse).ok());
  GameOptions from_file = quiet_options();
  from_file.creature_file = file;
  {
    Game as_saved;
    REQUIRE(as_saved.init(from_file).ok());
    CHECK(as_saved.world().player()->creature().scale == Approx(horse->scale));
  }
  from_file.size = SizeChoice{false, 1.5f};
  Game resized;
  REQUIRE(resized.init(from_file).ok());
  CHECK(resized.world().player()->creature().scale == Approx(0.0015f));
}
