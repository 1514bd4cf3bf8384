#include "ossa/level/level_art.h"

#include <cctype>
#include <filesystem>

namespace ossa {

int64_t LevelArt::tile_count() const {
  int64_t n = 0;
  for (const ArtLayer& l : layers) {
    for (const ArtBatch& b : l.batches) n += static_cast<int64_t>(b.tiles.size());
  }
  return n;
}

int LevelArt::add_image(const std::string& path, const std::string& source, int width_px, int height_px) {
  for (size_t i = 0; i < images.size(); ++i) {
    if (images[i].path == path) {
      // A later declaration may know the size an earlier one left out.
      if (images[i].width_px == 0) images[i].width_px = width_px;
      if (images[i].height_px == 0) images[i].height_px = height_px;
      return static_cast<int>(i);
    }
  }
  images.push_back({path, source, width_px, height_px});
  return static_cast<int>(images.size()) - 1;
}

std::optional<glm::vec4> parse_hex_colour(const std::string& s) {
  if ((s.size() != 7 && s.size() != 9) || s[0] != '#') return std::nullopt;
  for (size_t i = 1; i < s.size(); ++i) {
    if (!std::isxdigit(static_cast<unsigned char>(s[i]))) return std::nullopt;
  }
  const auto byte = [&](size_t at) { return static_cast<float>(std::stoi(s.substr(at, 2), nullptr, 16)) / 255.0f; };
  if (s.size() == 7) return glm::vec4(byte(1), byte(3), byte(5), 1.0f);
  return glm::vec4(byte(3), byte(5), byte(7), byte(1));  // #AARRGGBB
}

std::string art_path_near(const std::string& file, const std::string& source) {
  namespace fs = std::filesystem;
  const fs::path src(source);
  if (src.is_absolute()) return src.lexically_normal().string();
  std::string f = file;
  std::error_code ec;
  if (const size_t hash = f.rfind('#'); hash != std::string::npos && !fs::exists(f, ec)) f.resize(hash);
  return (fs::path(f).parent_path() / src).lexically_normal().string();
}

}  // namespace ossa
