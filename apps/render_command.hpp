#pragma once

#include <string>

#include "run_frames.hpp"

namespace tide::app {

struct RenderOptions {
  FrameSelection input;            // output directory by default <run directory>/render
  std::string field = "velocity";  // a vector field is drawn by its magnitude
  std::string colormap = "viridis";
  std::string size = "1280x720";
  bool surface = false;           // 3D: draw the fluid surface (tide surface's mesh) instead of the particles
  bool heatmap = false;           // 2D: the points' kernel-summed number density (a crowd's persons/m²) over the floor
  double smoothing_length = 0.5;  // m, h of the heat map's Wendland C2 kernel
  double heatmap_max = 6;         // the top of the heat map's colour scale, from 0
};

/// `tide render`: each selected frame of a run as a PNG (particles coloured by a field on one
/// colour scale for all frames, a colour bar and the time; with `surface`, the shaded surface mesh
/// of a 3D frame and the time; with `heatmap`, the number density of a 2D frame's points on every pixel, from 0 to
/// heatmap_max), then movie.mp4 where ffmpeg is installed. Exit code 2 with a message for a missing run,
/// a bad frame range, size or colour map, a field the frames lack, --surface or --heatmap for a run of the other
/// dimension, or an unreadable frame.
int render_frames(const RenderOptions& options);

}  // namespace tide::app
