// The HUD's modes: what a player sees by default (name, km/h, gait), what the developer mode
// adds (m/s, bands, Froude, frame times), and H's order.

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "ossa/editor/hud.h"

using namespace ossa;

namespace {

bool has(const std::vector<std::string>& lines, const std::string& text) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

HudInfo horse_trotting() {
  HudInfo info;
  info.creature = "horse";
  info.speed = -3.0f;  // m/s, to the left
  info.walk_speed = 1.99f;
  info.run_speed = 4.45f;
  info.family = "cursorial";
  info.gaits = {"walk", "trot", "gallop"};
  info.mid_speed = 1.99f;
  info.fast_speed = 4.17f;
  info.gait = "trot";
  info.locomotion = "grounded";
  info.froude = 0.83f;
  info.input = "keyboard";
  return info;
}

}  // namespace

TEST_CASE("the player HUD shows the name, the speed in km/h and the gait, developer figures only in developer mode", "[editor]") {
  const HudInfo info = horse_trotting();
  const auto player = hud_lines(info, HudMode::kPlayer, 60.0f);
  REQUIRE(player.size() >= 2);
  CHECK(player[0] == "horse (cursorial)");
  CHECK(player[1] == "10.8 km/h  trot");
  CHECK_FALSE(has(player, "Froude"));
  CHECK_FALSE(has(player, "bands"));
  CHECK_FALSE(has(player, "FPS"));
  CHECK(has(player, "F2"));

  HudInfo air = info;
  air.locomotion = "airborne";
  CHECK(hud_lines(air, HudMode::kPlayer, 60.0f)[1] == "10.8 km/h  trot (airborne)");

  const auto dev = hud_lines(info, HudMode::kDeveloper, 60.0f);
  CHECK(dev[0] == "horse (cursorial)");
  CHECK(has(dev, "Froude    0.83"));
  CHECK(has(dev, "walk < 1.99 < trot < 4.17 < gallop"));
  CHECK(has(dev, "FPS"));
  CHECK(has(dev, "-3.00 m/s"));
  CHECK(hud_lines(info, HudMode::kOff, 60.0f).empty());
}

TEST_CASE("the HUD shows the creature's size and why it stands blocked", "[editor]") {
  HudInfo info = horse_trotting();
  info.hip_height = 1.07f;
  CHECK(hud_lines(info, HudMode::kPlayer, 60.0f)[0] == "horse (cursorial), hip 1.07 m");
  info.creature = "frog";
  info.hip_height = 0.031f;
  info.blocked = "blocked: a step 0.25 m high ahead, its legs climb 0.01 m; too high to jump: a jump rises 0.03 m";
  const auto player = hud_lines(info, HudMode::kPlayer, 60.0f);
  CHECK(player[0] == "frog (cursorial), hip 3.1 cm");
  CHECK(has(player, "too high to jump"));
  CHECK(has(hud_lines(info, HudMode::kDeveloper, 60.0f), "its legs climb 0.01 m"));
}

TEST_CASE("H cycles the HUD: player, developer, off", "[editor]") {
  Hud hud;
  CHECK(hud.mode == HudMode::kPlayer);
  hud.cycle();
  CHECK(hud.mode == HudMode::kDeveloper);
  hud.cycle();
  CHECK(hud.mode == HudMode::kOff);
  hud.cycle();
  CHECK(hud.mode == HudMode::kPlayer);
  CHECK(std::string(hud_mode_name(HudMode::kDeveloper)) == "developer");
}
