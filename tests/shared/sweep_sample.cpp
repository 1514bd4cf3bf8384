#include "shared/sweep_sample.h"

#include <cstdlib>
#include <fstream>
#include <map>

#include "ossa/assert.h"
#include "shared/scenes.h"

namespace ossa::test {

namespace {

struct Sample {
  std::vector<std::string> animals;
  std::vector<uint64_t> seeds;
};

// Sweep key -> its sample: lines "KEY animal NAME" and "KEY seed N".
const Sample& sample(const std::string& key) {
  static const std::map<std::string, Sample> all = [] {
    std::map<std::string, Sample> out;
    const std::string path = scenes::source_path("tests/shared/sanitizer_sample.txt");
    std::ifstream in(path);
    OSSA_ASSERT(in.good(), "tests/shared/sanitizer_sample.txt is missing");
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      for (const char* kind : {" animal ", " seed "}) {
        const size_t at = line.find(kind);
        if (at == std::string::npos) continue;
        Sample& s = out[line.substr(0, at)];
        const std::string rest = line.substr(at + std::string(kind).size());
        if (kind[1] == 'a') s.animals.push_back(rest);
        else s.seeds.push_back(std::stoull(rest));
        break;
      }
    }
    return out;
  }();
  static const Sample none;
  const auto it = all.find(key);
  OSSA_ASSERT(!sampling() || it != all.end(), "tests/shared/sanitizer_sample.txt has no sample for a sweep (tools/sanitizer-sample --write)");
  return it != all.end() ? it->second : none;
}

// OSSA_SWEEP_ONLY, or "" when unset.
std::string only() {
  const char* v = std::getenv("OSSA_SWEEP_ONLY");
  return v ? std::string(v) : std::string();
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  for (const std::string& x : v) {
    if (x == s) return true;
  }
  return false;
}

}  // namespace

bool sampling() {
  const char* v = std::getenv("OSSA_SAMPLE");
  return kSanitized || (v && std::string(v) == "1");
}

std::vector<std::string> sweep_animals(const std::string& key) {
  const std::string one = only();
  std::vector<std::string> names;
  for (const Animal& animal : scenes::generator().dataset().animals) {
    if (!one.empty() ? animal.name == one : !sampling() || contains(sample(key).animals, animal.name)) names.push_back(animal.name);
  }
  return names;
}

std::vector<uint64_t> sweep_seeds(const std::string& key, uint64_t n) {
  const std::string one = only();
  std::vector<uint64_t> seeds;
  for (uint64_t seed = 1; seed <= n; ++seed) {
    bool keep = !sampling();
    if (!one.empty()) {
      keep = one == "seed:" + std::to_string(seed);
    } else if (sampling()) {
      for (uint64_t s : sample(key).seeds) keep = keep || s == seed;
    }
    if (keep) seeds.push_back(seed);
  }
  return seeds;
}

}  // namespace ossa::test
