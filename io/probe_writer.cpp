#include "tide/io/probe_writer.hpp"

#include <string>
#include <utility>
#include <vector>

#include "scene_text.hpp"

namespace tide::io {
namespace {

std::vector<std::string> probe_comments(const scene::Scene& scene) {
  std::vector<std::string> comments{"TideSPH probes of scene " + scene.source};
  for (const scene::Probe& probe : scene.probes) {
    const bool pressure = probe.type == scene::ProbeType::pressure;
    std::string comment = probe.name + (pressure ? ": pressure (Pa) at " : ": water_height (m) above ") +
                          vector_text(probe.position, scene.dimension);
    if (probe.sensor) {
      comment += ", mean over a sensing face " + format_number(probe.sensor->diameter) + " m across, normal " +
                 vector_text(probe.sensor->normal, scene.dimension);
    }
    comments.push_back(std::move(comment));
  }
  return comments;
}

std::vector<std::string> probe_columns(const scene::Scene& scene) {
  std::vector<std::string> columns;
  for (const scene::Probe& probe : scene.probes) columns.push_back(probe.name);
  return columns;
}

}  // namespace

ProbeWriter::ProbeWriter(std::filesystem::path file, const scene::Scene& scene)
    : SeriesWriter(std::move(file), probe_comments(scene), probe_columns(scene)) {}

}  // namespace tide::io
