#include "tide/io/crowd_writer.hpp"

#include <string>
#include <utility>
#include <vector>

namespace tide::io {
namespace {

std::vector<std::string> crowd_columns(const scene::Scene& scene) {
  std::vector<std::string> columns{"inside"};
  for (const scene::CrowdExit& exit : scene.crowd->exits) columns.push_back("out_" + exit.name);
  columns.emplace_back("mean_density");
  columns.emplace_back("mean_speed");
  for (const char* peak : {"peak_density", "peak_x", "peak_y", "peak_time"}) columns.emplace_back(peak);
  return columns;
}

}  // namespace

CrowdWriter::CrowdWriter(std::filesystem::path file, const scene::Scene& scene)
    : SeriesWriter(std::move(file),
                   {"TideSPH crowd of scene " + scene.source,
                    "inside: agents in the domain; out_<exit>: agents that left through that exit so far; "
                    "mean_density: the kernel-summed density averaged over the agents inside, persons/m^2; "
                    "mean_speed: their mean speed, m/s",
                    "peak_density, peak_x, peak_y, peak_time: the largest density an agent has had so far, where and "
                    "when (a crush risk above 5 persons/m^2)"},
                   crowd_columns(scene)) {}

}  // namespace tide::io
