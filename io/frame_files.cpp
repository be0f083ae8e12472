#include "tide/io/frame_files.hpp"

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <string>
#include <system_error>

namespace tide::io {

std::vector<FrameFile> list_frames(const std::filesystem::path& run_directory) {
  std::error_code error;
  if (!std::filesystem::is_directory(run_directory, error))
    throw std::invalid_argument(run_directory.string() + ": no such run directory");
  static const std::regex frame_name(R"(frames_([0-9]{6,})\.h5)");
  std::vector<FrameFile> frames;
  for (const auto& entry : std::filesystem::directory_iterator(run_directory)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(name, match, frame_name))
      frames.push_back({std::stoul(match[1].str()), entry.path()});
  }
  if (frames.empty())
    throw std::invalid_argument(run_directory.string() + ": no frame files (frames_NNNNNN.h5) in this directory");
  std::sort(frames.begin(), frames.end(), [](const FrameFile& a, const FrameFile& b) { return a.number < b.number; });
  return frames;
}

}  // namespace tide::io
