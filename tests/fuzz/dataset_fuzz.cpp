// Fuzzes the examples-file loader (DESIGN.md §11: no input file, however malformed, may crash).
// Any input must give either a Dataset whose every animal passes the documented ranges, or an
// error message naming the file.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "ossa/gen/dataset.h"
#include "ossa/gen/pca_model.h"
#include "ossa/io/json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ossa::Result<ossa::Dataset> d = ossa::parse_dataset(text, "fuzz.json");
  if (!d.ok()) {
    if (d.message().rfind("fuzz.json", 0) != 0) std::abort();  // errors name the file
    return 0;
  }
  if (d->animals.empty()) std::abort();
  for (const ossa::Animal& a : d->animals) {
    if (a.name.empty() || a.wings < 0 || a.wings > 1 || a.leg_pairs < 0 || a.leg_pairs > 2) std::abort();
    if (!(a.weight_kg >= 0.0)) std::abort();
    for (const auto& p : a.spine) {
      if (!(p.x >= 0.0f && p.x <= 1000.0f && p.y >= 0.0f && p.y <= 1000.0f)) std::abort();
    }
    if (d->find(a.name) == nullptr) std::abort();
    const ossa::PcaVector v = ossa::to_vector(a);
    if (!v.allFinite()) std::abort();
  }
  return 0;
}
