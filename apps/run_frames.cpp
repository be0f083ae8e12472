#include "run_frames.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "tide/surface/particle_spacing.hpp"

namespace tide::app {
namespace {

/// A frame number, or nothing for empty text; std::invalid_argument for anything else.
std::optional<std::size_t> frame_number(const std::string& text, const std::string& range) {
  if (text.empty()) return std::nullopt;
  std::size_t number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument("--frames " + range + ": expected A:B, A:, :B or A with frame numbers A and B");
  return number;
}

}  // namespace

std::vector<FrameFile> select_frames(const std::vector<FrameFile>& frames, const std::string& range) {
  const std::size_t colon = range.find(':');
  const std::optional<std::size_t> first = frame_number(range.substr(0, colon), range);
  const std::optional<std::size_t> last =
      colon == std::string::npos ? first : frame_number(range.substr(colon + 1), range);
  const std::size_t lowest = first.value_or(0), highest = last.value_or(std::numeric_limits<std::size_t>::max());
  if (lowest > highest) throw std::invalid_argument("--frames " + range + ": the first frame is after the last");
  std::vector<FrameFile> selected;
  std::copy_if(frames.begin(), frames.end(), std::back_inserter(selected),
               [&](const FrameFile& frame) { return frame.number >= lowest && frame.number <= highest; });
  if (selected.empty())
    throw std::invalid_argument("--frames " + range + ": the run has frames " + std::to_string(frames.front().number) +
                                " to " + std::to_string(frames.back().number) + " only");
  return selected;
}

FramePositions take_positions(io::Frame& frame) {
  io::FrameDataset& position = frame.datasets.at("position");
  return {frame.time, static_cast<int>(position.shape[1]), std::move(position.values)};
}

double particle_spacing(const FrameSelection& selection, const FrameFile& first_frame) {
  if (selection.particle_spacing) return *selection.particle_spacing;
  io::Frame frame = io::read_frame(first_frame.path);
  const FramePositions first = take_positions(frame);
  const double spacing = first.dimension == 2 ? surface::median_neighbour_distance<2>(first.values)
                                              : surface::median_neighbour_distance<3>(first.values);
  std::printf("particle spacing %g m: the median nearest-neighbour distance in %s (--spacing sets it)\n", spacing,
              first_frame.path.filename().c_str());
  return spacing;
}

std::filesystem::path picture_directory(const FrameSelection& selection, const std::string& folder) {
  const std::filesystem::path directory =
      selection.output_directory.empty() ? selection.run_directory / folder : selection.output_directory;
  std::filesystem::create_directories(directory);
  return directory;
}

std::string wall_series_name(const std::string& contact) {
  std::string name;
  for (const char c : contact) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      name += c;
    } else if (!name.empty() && name.back() != '_') {
      name += '_';
    }
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

std::string numbered_file_name(const std::string& stem, std::size_t number, const std::string& extension) {
  char digits[24];
  std::snprintf(digits, sizeof digits, "%06zu", number);
  return stem + "_" + digits + extension;
}

}  // namespace tide::app
