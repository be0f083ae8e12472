#pragma once

#include <filesystem>

#include "tide/core/scene.hpp"
#include "tide/io/series_writer.hpp"

namespace tide::io {

/// Writes the recovery of output.recovery as one CSV file (docs/output.md, "recovery.csv"):
///
///   # TideSPH recovery of scene <scene source>
///   # material <name> in the region [min] to [max]; initial mass <M0> (kg, per metre in 2D)
///   time,mass,recovery
///   <t>,<M>,<1 - M/M0>
///
/// (SeriesWriter: shortest round-trip numbers, the file replaced whole by `write`).
class RecoveryWriter : public SeriesWriter {
 public:
  RecoveryWriter(std::filesystem::path file, const scene::Scene& scene, double initial_mass);
};

}  // namespace tide::io
