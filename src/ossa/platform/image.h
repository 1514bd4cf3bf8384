#pragma once
// Loading images through SDL2_image (PNG, JPEG, ...) into an Image (draw/image.h: RGBA pixels
// on the CPU, rows top to bottom). Used by textures, level art and frame capture.

#include <string>

#include "ossa/draw/image.h"
#include "ossa/io/result.h"

namespace ossa {

// Loads an image file as RGBA: a regular file of at most kMaxImageFileBytes, PNG, JPEG or BMP,
// whose size check_image accepts from its header before anything is decoded (io/image_info.h).
// Errors name the file and the reason.
Result<Image> load_image(const std::string& path);

}  // namespace ossa
