#pragma once

// The frames of a run directory as `tide run` writes them (docs/output.md): frames_NNNNNN.h5, the
// selection `--frames A:B` makes of them and what the commands that turn frames into pictures
// (tide surface, tide render) take from them.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tide/io/frame_files.hpp"
#include "tide/io/frame_writer.hpp"

namespace tide::app {

/// The options every picture command takes.
struct FrameSelection {
  std::filesystem::path run_directory;
  std::string frames;                      // "A:B", "A:", ":B", "A" or "" (all)
  std::filesystem::path output_directory;  // empty: a folder of the command's in the run directory
  std::optional<double> particle_spacing;  // empty: estimated from the run's first frame
};

using io::FrameFile;
using io::list_frames;

/// The frames numbered within `range`: "A:B" (A to B, both included), "A:" (from A), ":B" (to B),
/// "A" (frame A alone) or "" (all). std::invalid_argument for a range that is not one of these
/// forms, has A > B, or selects no frame of the run.
std::vector<FrameFile> select_frames(const std::vector<FrameFile>& frames, const std::string& range);

/// A frame's particle positions, row-major, and its dimension.
struct FramePositions {
  double time = 0;
  int dimension = 0;
  std::vector<double> values;
};

/// Takes the positions out of `frame` (read_frame has checked they are there, (N, 2) or (N, 3)).
FramePositions take_positions(io::Frame& frame);

/// selection.particle_spacing, or else the median nearest-neighbour distance of the particles in
/// `first_frame`, which the run started from on its lattice (printed, with how to set it).
double particle_spacing(const FrameSelection& selection, const FrameFile& first_frame);

/// selection.output_directory, or else `folder` in the run directory; created if it is not there.
std::filesystem::path picture_directory(const FrameSelection& selection, const std::string& folder);

/// The stem of the frame files of a wall contact, from its name or key path: "walls.obstacles[2]"
/// -> "walls_obstacles_2", "free-slip walls" -> "free_slip_walls" (letters and digits kept, runs
/// of others one '_').
std::string wall_series_name(const std::string& contact);

/// "<stem>_000012<extension>".
std::string numbered_file_name(const std::string& stem, std::size_t number, const std::string& extension);

}  // namespace tide::app
