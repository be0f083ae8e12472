#pragma once

#include <string>

#include "run_frames.hpp"

namespace tide::app {

struct RenderOptions {
  FrameSelection input;            // output directory by default <run directory>/render
  std::string field = "velocity";  // a vector field is drawn by its magnitude
  std::string colormap = "viridis";
  std::string size = "1280x720";
};

/// `tide render`: each selected frame of a run as a PNG (particles coloured by a field on one
/// colour scale for all frames, a colour bar and the time), then movie.mp4 where ffmpeg is
/// installed. Exit code 2 with a message for a missing run, a bad frame range, size or colour
/// map, a field the frames lack, or an unreadable frame.
int render_frames(const RenderOptions& options);

}  // namespace tide::app
