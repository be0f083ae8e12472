#pragma once

// The frames of a run directory as `tide run` writes them (docs/output.md): frames_NNNNNN.h5, and
// the selection `--frames A:B` makes of them, for the commands that turn frames into pictures.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace tide::app {

struct FrameFile {
  std::size_t number = 0;
  std::filesystem::path path;
};

/// The frame files of `run_directory` in frame order; std::invalid_argument naming the directory
/// when it does not exist or holds no frame file.
std::vector<FrameFile> list_frames(const std::filesystem::path& run_directory);

/// The frames numbered within `range`: "A:B" (A to B, both included), "A:" (from A), ":B" (to B),
/// "A" (frame A alone) or "" (all). std::invalid_argument for a range that is not one of these
/// forms, has A > B, or selects no frame of the run.
std::vector<FrameFile> select_frames(const std::vector<FrameFile>& frames, const std::string& range);

}  // namespace tide::app
