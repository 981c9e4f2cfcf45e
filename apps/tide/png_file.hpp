#pragma once
// PNG files through stb_image_write, written atomically (temporary file + rename), so a
// crash or a full disk never leaves half a frame.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace tide::cli {

/// Write RGBA pixels, top row first. Throws std::runtime_error naming the file.
void writePng(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba);

}  // namespace tide::cli
