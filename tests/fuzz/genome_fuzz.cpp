// Fuzzes the genome loader and the builder behind it (DESIGN.md §11: no input file, however
// malformed, may crash). Any input must give an error naming the file, or a genome that builds
// into a valid skeleton or fails with an error.

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "ossa/gen/genome.h"
#include "ossa/gen/skeleton_builder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ossa::Result<ossa::Genome> g = ossa::parse_genome(text, "fuzz.creature.json");
  if (!g.ok()) {
    if (g.message().rfind("fuzz.creature.json", 0) != 0) std::abort();
    return 0;
  }
  ossa::Result<ossa::Creature> c = ossa::build_creature(*g);
  if (c.ok() && !c->skeleton.is_valid()) std::abort();
  return 0;
}
