#pragma once

#include <filesystem>
#include <optional>

#include "tide/core/scene.hpp"

namespace tide::app {

/// Exit codes of the `tide` command.
enum ExitCode : int { exit_ok = 0, exit_failure = 1, exit_bad_input = 2, exit_unstable = 3 };

/// Reads and checks a scene file, warning about settings likely to go unstable; prints why and
/// gives nothing when the file is not a valid scene.
std::optional<scene::Scene> load_scene(const std::filesystem::path& file);

struct RunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path output_directory;  // empty: runs/<scene name>
  std::optional<double> until;             // overrides the scene's end time
  bool quiet = false;
  bool vtk = false;                        // VTK files beside the HDF5 frames, as the scene's output.vtk
  std::optional<double> checkpoint_every;  // s of simulated time between checkpoints
  std::optional<double> checkpoint_wall;   // s of wall-clock time between checkpoints
  std::filesystem::path resume;            // a run directory to continue from its checkpoint
};

/// The checkpoint of a run directory (docs/output.md, "Checkpoints").
std::filesystem::path checkpoint_path(const std::filesystem::path& run_directory);

/// Where `tide run` writes: options.resume, else options.output_directory, else runs/<scene
/// file's stem>.
std::filesystem::path run_output_directory(const RunOptions& options);

/// `tide run`: reads the scene, runs it with progress, writes frames and prints a summary.
int run_scene(const RunOptions& options);

/// `tide check`: reads and validates the scene and builds its particles, without stepping.
int check_scene(const std::filesystem::path& scene_file);

}  // namespace tide::app
