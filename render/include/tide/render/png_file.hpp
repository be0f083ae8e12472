#pragma once

#include <filesystem>

#include "tide/render/image.hpp"

namespace tide::render {

/// Writes `image` as an 8-bit RGB PNG through libpng, atomically (io/include/tide/io/atomic_file.hpp):
/// a killed run leaves the old file or the new one. std::runtime_error naming the file on failure.
void write_png(const std::filesystem::path& path, const Image& image);

}  // namespace tide::render
