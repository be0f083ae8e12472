#pragma once

#include <filesystem>

#include "tide/core/scene.hpp"
#include "tide/io/series_writer.hpp"

namespace tide::io {

/// Writes a crowd's counts as one CSV file (docs/crowds.md, "Output"):
///
///   # TideSPH crowd of scene <scene source>
///   # agents: inside the domain; out_<exit>: left through that exit so far; ...
///   time,inside,out_<exit>,...,mean_density,mean_speed,peak_density,peak_x,peak_y,peak_time
///
/// (SeriesWriter: shortest round-trip numbers, the file replaced whole by `write`).
class CrowdWriter : public SeriesWriter {
 public:
  /// `scene` must have a crowd.
  CrowdWriter(std::filesystem::path file, const scene::Scene& scene);
};

}  // namespace tide::io
