#pragma once
// Hud — the overlay (Dear ImGui, DESIGN.md §8) in three modes, cycled by H (off, player,
// developer): for players the creature's name and size, its speed in km/h and its gait, why it
// stands blocked when it does (a step too high for a small creature), with a line of key help; for developers also the speed in m/s with the walk and run speeds, the gait bands,
// the Froude number, the frame rate, a graph of recent frame times, the input and all the keys.
// Needs a current ImGui frame (NewFrame called); draws one small window in a corner.

#include <array>
#include <string>
#include <vector>

namespace ossa {

// What the HUD shows this frame.
struct HudInfo {
  std::string creature;        // the player's creature name
  float hip_height = 0.0f;     // its size: the hip height, m (Animator::hip_height(); 0: not shown)
  std::string blocked;         // why it stands blocked (describe_block), or ""
  float speed = 0.0f;          // m/s, signed (+ right)
  float walk_speed = 0.0f;     // m/s at Froude 0.5, for reference
  float run_speed = 0.0f;      // m/s of the full run (Animator::run_speed())
  // The gait family (gait_family_name) and where its gaits change, m/s (Animator::gait_bands()):
  // its walk, middle and fast gaits' names and the speeds from walk to the middle gait and on
  // to the fast one (0 where it has no such change).
  std::string family;
  std::array<std::string, 3> gaits;
  float mid_speed = 0.0f, fast_speed = 0.0f;
  std::string gait;            // gait_name(animator.gait())
  std::string locomotion;      // locomotion_name(animator.locomotion()): grounded, airborne...
  float froude = 0.0f;         // v² / (g·h)
  int tick_hz = 120;           // simulation rate
  std::string input;           // "keyboard", the gamepad's name, "replay", "demo"
  std::string status;          // a transient message ("screenshot out/shot-0001.png"), or ""
  bool recording = false;      // a replay is being recorded
  bool gif = false;            // a GIF is being captured
};

enum class HudMode { kOff, kPlayer, kDeveloper };

// H's order: player -> developer -> off -> player.
HudMode next_hud_mode(HudMode mode);
const char* hud_mode_name(HudMode mode);  // "off", "player", "developer"

// The text lines the HUD shows in `mode` (the developer mode also draws the frame-time graph
// after its FPS line). Empty for kOff.
std::vector<std::string> hud_lines(const HudInfo& info, HudMode mode, float fps);

class Hud {
 public:
  static constexpr int kHistory = 240;  // frame times kept for the graph

  // Adds one frame's wall time (seconds) to the FPS average and the graph.
  void add_frame_time(float seconds);
  // Frames per second over the kept history (0 before the first frame).
  float fps() const;
  // Draws the overlay in its mode.
  void draw(const HudInfo& info);
  void cycle() { mode = next_hud_mode(mode); }

  HudMode mode = HudMode::kPlayer;

 private:
  std::array<float, kHistory> frame_millis_{};  // ring buffer, milliseconds
  int next_ = 0;
  int count_ = 0;
};

}  // namespace ossa
