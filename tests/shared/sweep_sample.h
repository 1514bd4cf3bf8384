#pragma once
// Every-animal sweeps and their samples under the sanitizers. tools/test runs every sweep in
// full in the Release build; in the ASan+UBSan build each sweep visits its own sample, listed
// under its key in tests/shared/sanitizer_sample.txt: the example animals (and random
// creatures' seeds) that together reach every line and branch outcome of src/ossa that the
// full sweep reaches. tools/sanitizer-sample chooses the samples and checks them from coverage.

#include <cstdint>
#include <string>
#include <vector>

namespace ossa::test {

// A sanitizer build (OSSA_SANITIZE, CMakeLists.txt)?
#if defined(OSSA_SANITIZED)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// Do sweeps visit the sample: a sanitizer build, or OSSA_SAMPLE=1 in the environment?
bool sampling();

// The example animals sweep `key` visits, in the dataset's order: all 44, or its sample. With
// OSSA_SWEEP_ONLY=NAME in the environment, that one alone (tools/sanitizer-sample measures
// what each reaches); with OSSA_SWEEP_ONLY=seed:N, none.
std::vector<std::string> sweep_animals(const std::string& key);

// The seeds of random creatures 1..n sweep `key` visits: all of them, or its sample's; with
// OSSA_SWEEP_ONLY=seed:N that one alone, with OSSA_SWEEP_ONLY=NAME none.
std::vector<uint64_t> sweep_seeds(const std::string& key, uint64_t n);

}  // namespace ossa::test
