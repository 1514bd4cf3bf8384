// The editor windows' first-use layout fits 1280 x 720 and 1920 x 1080: every window on
// screen below the menu bar, the middle (where the camera keeps the player) free.

#include <catch2/catch.hpp>

#include "ossa/editor/editor_layout.h"

using namespace ossa;

TEST_CASE("editor windows open on screen, below the menu bar, leaving the player's middle free", "[editor]") {
  for (const glm::vec2 display : {glm::vec2(1280.0f, 720.0f), glm::vec2(1920.0f, 1080.0f), glm::vec2(1024.0f, 600.0f)}) {
    INFO(display.x << " x " << display.y);
    const auto layout = editor_layout(display);
    for (int i = 0; i < kEditorWindowCount; ++i) {
      INFO("window " << i);
      const WindowRect& r = layout[static_cast<size_t>(i)];
      CHECK(r.pos.x >= 0.0f);
      CHECK(r.pos.y >= kMenuBarHeight);
      CHECK(r.pos.x + r.size.x <= display.x);
      CHECK(r.pos.y + r.size.y <= display.y);
      CHECK(r.size.x >= 250.0f);  // wide enough for the fields
      CHECK(r.size.y >= 400.0f);
      // The player: around the centre, from a bit above the middle to its feet in the lower part.
      const float px0 = 0.37f * display.x, px1 = 0.63f * display.x;
      const bool clear = r.pos.x + r.size.x <= px0 || r.pos.x >= px1;
      CHECK(clear);
    }
  }
}
