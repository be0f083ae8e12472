#include "run_walls.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>

#include "run_frames.hpp"
#include "tide/io/frame_writer.hpp"

namespace tide::app {
namespace {

/// The series names of the bodies bodies.csv has columns for ("walls.obstacles[2].x", ... ->
/// "walls_obstacles_2"); none without the file.
std::set<std::string> body_series(const std::filesystem::path& run_directory) {
  std::set<std::string> names;
  std::ifstream file(run_directory / "bodies.csv");
  std::string line;
  while (std::getline(file, line) && (line.empty() || line.front() == '#')) continue;
  std::size_t start = 0;
  while (start < line.size()) {
    const std::size_t comma = std::min(line.find(',', start), line.size());
    const std::string column = line.substr(start, comma - start);
    const std::size_t dot = column.rfind('.');
    if (dot != std::string::npos) names.insert(wall_series_name(column.substr(0, dot)));
    start = comma + 1;
  }
  return names;
}

}  // namespace

RunWalls::RunWalls(const std::filesystem::path& run_directory) {
  static const std::regex frame_name(R"((.+)_([0-9]{6,})\.h5)");
  const std::set<std::string> bodies = body_series(run_directory);
  std::map<std::string, Series> by_stem;
  for (const auto& entry : std::filesystem::directory_iterator(run_directory)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || !std::regex_match(name, match, frame_name) || match[1].str() == "frames") continue;
    Series& series = by_stem[match[1].str()];
    series.frames.emplace_back(std::stoul(match[2].str()), entry.path());
    series.body = bodies.count(match[1].str()) > 0;
  }
  for (auto& [stem, series] : by_stem) {
    std::sort(series.frames.begin(), series.frames.end());
    series_.push_back(std::move(series));
  }
}

WallParticles RunWalls::at(std::size_t frame) const {
  WallParticles particles;
  for (const Series& series : series_) {
    const auto after = std::upper_bound(series.frames.begin(), series.frames.end(), frame,
                                        [](std::size_t number, const auto& file) { return number < file.first; });
    if (after == series.frames.begin()) continue;
    io::Frame read = io::read_frame(std::prev(after)->second);
    const std::vector<double>& positions = read.datasets.at("position").values;
    std::vector<double>& into = series.body ? particles.bodies : particles.walls;
    into.insert(into.end(), positions.begin(), positions.end());
  }
  return particles;
}

}  // namespace tide::app
