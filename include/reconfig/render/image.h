#pragma once
/// @file
/// An RGBA8 image read back from the renderer, and writing it as PNG.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace reconfig::render {

/// width × height pixels, 4 bytes each (R, G, B, A), rows from the top of the picture down.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< width · height · 4 bytes

  /// The pixel in column x (from the left) and row y (from the top).
  std::array<std::uint8_t, 4> pixel(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
  }
};

/// Writes `image` as an 8-bit RGBA PNG (stb_image_write). Throws `reconfig::InputError`
/// naming the path when the file cannot be written.
void write_png(const std::filesystem::path& path, const Image& image);

}  // namespace reconfig::render
