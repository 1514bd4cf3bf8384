#pragma once
// Controls — what a player (or an NPC brain, or a replay) asks of a creature in one tick.
// Produced by the platform's Gamepad / MouseKeyboardInput, recorded by Replay.

namespace ossa {

struct Controls {
  float move_x = 0.0f;  // stick, [-1, 1]: the sign is the direction, the magnitude the speed
  bool run = false;     // run button: the stick's full range reaches the run speed
  bool jump = false;    // jump button held (a creature on the ground jumps when it goes down)

  friend bool operator==(const Controls& a, const Controls& b) {
    return a.move_x == b.move_x && a.run == b.run && a.jump == b.jump;
  }
};

}  // namespace ossa
