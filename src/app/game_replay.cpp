// Game — replays (recording the player's controls, their files) and the headless demo's
// script.

#include <cstdio>
#include <filesystem>

#include "app/game_impl.h"

namespace ossa {

// ---- Replays and the demo -------------------------------------------------------------------

std::string Game::Impl::next_free_replay_path() {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  for (int i = 1;; ++i) {
    char name[64];
    std::snprintf(name, sizeof(name), "/replay-%04d.replay.json", i);
    if (!std::filesystem::exists(out_dir + name, ec)) return out_dir + name;
  }
}

void Game::Impl::start_recording(World& world, const std::string& level, bool respawn) {
  // A replay starts from a freshly placed creature so playback can rebuild the exact state.
  if (respawn) {
    const Player& p = *world.player();
    const glm::vec2 at{p.animator().x(), player_root(1.0f).y + 0.5f};
    const int facing = p.animator().facing();
    if (p.is_character()) {
      world.spawn_player(p.character_ptr(), at, facing);
    } else {
      world.spawn_player(p.creature_ptr(), at, facing);
    }
    spawn = at;
    snapshot_all(world, true);
  }
  record = Replay{};
  record.tick_hz = world.tick_hz();
  record.level = level;
  if (world.player()->is_character()) {
    record.character = character_path;
  } else {
    record.creature = genome_to_json(genome);
  }
  record.spawn_ws = spawn;
  record.facing = world.player()->animator().facing();
  recording = true;
}

std::string Game::Impl::stop_recording(const std::string& path) {
  recording = false;
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  const Status s = save_replay(path, record);
  last_record_failed = !s.ok();
  const std::string msg = s.ok() ? "replay written: " + path : s.message();
  std::fprintf(stderr, "ossa: %s\n", msg.c_str());
  return msg;
}

Controls Game::Impl::demo_controls(uint64_t tick, int tick_hz) const {
  // The script (kDemoScript) loops.
  uint64_t total = 0;
  for (const ScriptSegment& s : demo) total += static_cast<uint64_t>(s.ticks(tick_hz));
  if (total == 0) return {};
  uint64_t t = tick % total;
  Controls previous;
  for (const ScriptSegment& s : demo) {
    previous = s.controls(previous);
    const uint64_t n = static_cast<uint64_t>(s.ticks(tick_hz));
    if (t < n) return previous;
    t -= n;
  }
  return {};
}

}  // namespace ossa
