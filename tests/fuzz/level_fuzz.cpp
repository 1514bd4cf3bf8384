// Fuzz target: level files, Tiled maps (JSON and XML) and LDtk projects. Every input goes
// through parse_level, import_tiled and parse_level_any (the content-dispatching loader behind
// load_level, without file access); whatever loads is queried, saved and re-read, which must
// give it back.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "ossa/io/json.h"
#include "ossa/level/level_io.h"
#include "ossa/level/level_load.h"
#include "ossa/level/tiled.h"

namespace {

void exercise(const ossa::Level& level) {
  const ossa::Box b = level.bounds();
  const glm::vec2 c = b.center();
  (void)level.ground_height_below(b.min_ws.x, c.x, b.max_ws.y, b.height());
  (void)level.overlaps(ossa::Box{b.min_ws, c});
  (void)level.sweep_box(ossa::Box::from_center(c, {0.1f, 0.1f}), {1.0f, -1.0f});
  ossa::Result<ossa::Level> again = ossa::parse_level(ossa::level_to_text(level), "again");
  if (!again.ok() || !(*again == level)) std::abort();  // a saved level must load back equal
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ossa::Result<ossa::Level> level = ossa::parse_level(text, "fuzz.json");
  if (level.ok()) exercise(*level);
  ossa::Result<ossa::Level> map = ossa::import_tiled(text, "fuzz.json");
  if (map.ok()) {
    exercise(*map);
    (void)ossa::export_tiled(*map);
  }
  for (const char* file : {"fuzz.tmj", "fuzz.ldtk"}) {
    ossa::Result<ossa::Level> any = ossa::parse_level_any(text, file, ossa::LevelLoadOptions{});
    if (any.ok()) exercise(*any);
  }
  return 0;
}
