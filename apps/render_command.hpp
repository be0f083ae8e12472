#pragma once

#include <string>

#include "run_frames.hpp"

namespace tide::app {

struct RenderOptions {
  FrameSelection input;            // output directory by default <run directory>/render
  std::string field = "velocity";  // a vector field is drawn by its magnitude
  std::string colormap = "viridis";
  std::string size = "1280x720";
  bool surface = false;  // 3D: draw the fluid surface (tide surface's mesh) instead of the particles
};

/// `tide render`: each selected frame of a run as a PNG (particles coloured by a field on one
/// colour scale for all frames, a colour bar and the time; with `surface`, the shaded surface mesh
/// of a 3D frame and the time), then movie.mp4 where ffmpeg is installed. Exit code 2 with a message for a missing run,
/// a bad frame range, size or colour map, a field the frames lack, --surface for a 2D run, or an unreadable frame.
int render_frames(const RenderOptions& options);

}  // namespace tide::app
