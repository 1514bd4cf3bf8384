#pragma once
// Scratch files for tests: a fresh folder under the system's temp directory, and the start of
// a PNG (signature and header chunk: all a decoder reads before it allocates).

#include <cstdint>
#include <filesystem>
#include <string>

namespace ossa::test {

// temp/NAME, emptied and created anew.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A PNG of w × h pixels, 1-bit greyscale (so a 55 KB file can declare 16384²), up to its
// header chunk's CRC (zeros).
inline std::string png_header(uint32_t w, uint32_t h) {
  std::string b("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (uint32_t v : {w, h}) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<char>((v >> s) & 0xFF));
  }
  return b + std::string("\x01\x00\x00\x00\x00\x00\x00\x00\x00", 9);
}

}  // namespace ossa::test
