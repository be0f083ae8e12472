#pragma once

// The frame files of a run directory as `tide run` writes them (docs/output.md): frames_NNNNNN.h5.

#include <cstddef>
#include <filesystem>
#include <vector>

namespace tide::io {

struct FrameFile {
  std::size_t number = 0;
  std::filesystem::path path;
};

/// The frame files of `run_directory` in frame order; std::invalid_argument naming the directory
/// when it does not exist or holds no frame file.
std::vector<FrameFile> list_frames(const std::filesystem::path& run_directory);

}  // namespace tide::io
