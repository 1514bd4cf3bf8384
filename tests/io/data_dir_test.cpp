#include "ossa/io/data_dir.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

using namespace ossa;

namespace {

// Sets OSSA_SOURCE_DIR (or unsets it, for nullopt) for one scope, then restores it.
class ScopedSourceDir {
 public:
  explicit ScopedSourceDir(const std::optional<std::string>& value) {
    if (const char* old = std::getenv("OSSA_SOURCE_DIR")) old_ = old;
    if (value) setenv("OSSA_SOURCE_DIR", value->c_str(), 1);
    else unsetenv("OSSA_SOURCE_DIR");
  }
  ~ScopedSourceDir() {
    if (old_) setenv("OSSA_SOURCE_DIR", old_->c_str(), 1);
    else unsetenv("OSSA_SOURCE_DIR");
  }

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST_CASE("data_path follows OSSA_SOURCE_DIR, else the compiled-in source tree", "[io]") {
  {
    ScopedSourceDir env(std::string("/somewhere/else"));
    CHECK(data_dir() == "/somewhere/else");
    CHECK(data_path("levels/default.json") == "/somewhere/else/levels/default.json");
  }
  for (const std::optional<std::string>& unset : {std::optional<std::string>(), std::optional<std::string>("")}) {
    ScopedSourceDir env(unset);
    INFO("OSSA_SOURCE_DIR " << (unset ? "empty" : "unset"));
    CHECK(data_dir() != "");
    CHECK(data_path("levels/default.json") == data_dir() + "/levels/default.json");
    CHECK(std::filesystem::is_regular_file(data_path("levels/default.json")));
    CHECK(std::filesystem::is_regular_file(data_path("assets/creatures/examples.json")));
  }
}
