#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace tide::app {

struct SurfaceOptions {
  std::filesystem::path run_directory;
  std::string frames;                      // "A:B", "A:", ":B", "A" or "" (all)
  std::filesystem::path output_directory;  // empty: <run directory>/surface
  std::optional<double> particle_spacing;  // empty: estimated from the run's first frame
  double smoothing_ratio = 1.2;
  double cell_ratio = 0.5;
};

/// `tide surface`: each selected frame of a run to its fluid surface, a closed triangle mesh
/// (surface_NNNNNN.ply and .obj) in 3D, the outline (outline_NNNNNN.svg and .csv) in 2D. Exit
/// code 2 with a message for a missing run, a bad frame range or an unreadable frame.
int reconstruct_surfaces(const SurfaceOptions& options);

}  // namespace tide::app
