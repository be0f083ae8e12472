#pragma once

#include <filesystem>

#include "tide/core/scene.hpp"
#include "tide/io/series_writer.hpp"

namespace tide::io {

/// Writes a run's probe readings as one CSV file (docs/output.md, "probes.csv"):
///
///   # TideSPH probes of scene <scene source>
///   # <name>: pressure (Pa) at [x, y(, z)]          one line per probe
///   # <name>: water_height (m) above [x, y(, z)]
///   time,<name>,<name>,...
///   <t>,<value>,<value>,...                           one row per reading, times in s
///
/// Rows take one value per probe, in the scene's order (SeriesWriter: shortest round-trip
/// numbers, the file replaced whole by `write`).
class ProbeWriter : public SeriesWriter {
 public:
  ProbeWriter(std::filesystem::path file, const scene::Scene& scene);
};

}  // namespace tide::io
