#include "ossa/io/image_info.h"

namespace ossa {

namespace {

uint32_t be32(std::string_view b, size_t at) {
  return uint32_t(uint8_t(b[at])) << 24 | uint32_t(uint8_t(b[at + 1])) << 16 | uint32_t(uint8_t(b[at + 2])) << 8 |
         uint32_t(uint8_t(b[at + 3]));
}
uint32_t be16(std::string_view b, size_t at) { return uint32_t(uint8_t(b[at])) << 8 | uint32_t(uint8_t(b[at + 1])); }
uint32_t le16(std::string_view b, size_t at) { return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8; }
uint32_t le32(std::string_view b, size_t at) { return le16(b, at) | le16(b, at + 2) << 16; }

// JPEG: the first start-of-frame marker (SOF0..SOF15 but DHT C4, JPG C8 and DAC CC) holds the
// height and width; the segments before it are skipped by their lengths.
Result<ImageInfo> jpeg_info(std::string_view b, std::string_view file) {
  size_t i = 2;
  while (i + 4 <= b.size()) {
    if (uint8_t(b[i]) != 0xFF) return Error::at(file, "", "is a broken JPEG file (expected a marker at byte " + std::to_string(i) + ")");
    const uint8_t marker = uint8_t(b[i + 1]);
    if (marker == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length
      i += 2;
      continue;
    }
    if (marker == 0xD9 || marker == 0xDA) break;  // end of image, start of scan: no frame header
    const size_t length = be16(b, i + 2);
    if (length < 2) break;
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      if (i + 9 > b.size()) break;
      return ImageInfo{"JPEG", be16(b, i + 7), be16(b, i + 5)};
    }
    i += 2 + length;
  }
  return Error::at(file, "", "is a broken JPEG file (no frame header before the image data)");
}

}  // namespace

Result<ImageInfo> read_image_info(std::string_view b, std::string_view file) {
  if (b.size() >= 24 && b.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) {
    if (b.substr(12, 4) != "IHDR") return Error::at(file, "", "is a broken PNG file (no IHDR chunk first)");
    return ImageInfo{"PNG", be32(b, 16), be32(b, 20)};
  }
  if (b.size() >= 4 && uint8_t(b[0]) == 0xFF && uint8_t(b[1]) == 0xD8 && uint8_t(b[2]) == 0xFF) return jpeg_info(b, file);
  if (b.size() >= 26 && b.substr(0, 2) == "BM") {
    const uint32_t header = le32(b, 14);
    if (header == 12) return ImageInfo{"BMP", le16(b, 18), le16(b, 20)};  // OS/2 BITMAPCOREHEADER
    const int32_t w = static_cast<int32_t>(le32(b, 18)), h = static_cast<int32_t>(le32(b, 22));
    // A negative height is a top-down bitmap.
    return ImageInfo{"BMP", w, h < 0 ? -static_cast<int64_t>(h) : h};
  }
  if (b.empty()) return Error::at(file, "", "is empty, expected a PNG, JPEG or BMP image");
  return Error::at(file, "", "is not a PNG, JPEG or BMP image (images must be one of these)");
}

Result<ImageInfo> check_image(std::string_view bytes, std::string_view file) {
  Result<ImageInfo> info = read_image_info(bytes, file);
  if (!info) return info;
  const int64_t w = info->width, h = info->height;
  if (w <= 0 || h <= 0) {
    return Error::at(file, "", "declares " + std::to_string(w) + " × " + std::to_string(h) + " pixels; expected at least 1 × 1");
  }
  if (w > kMaxImageSide || h > kMaxImageSide || w * h > kMaxImagePixels) {
    return Error::at(file, "", "is " + std::to_string(w) + " × " + std::to_string(h) + " pixels (" + info->format +
                                   "); images may be at most " + std::to_string(kMaxImageSide) + " pixels on a side and " +
                                   std::to_string(kMaxImagePixels) + " pixels in all");
  }
  return info;
}

}  // namespace ossa
