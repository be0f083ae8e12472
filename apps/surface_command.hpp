#pragma once

#include "run_frames.hpp"
#include "tide/surface/colour_field.hpp"

namespace tide::app {

struct SurfaceOptions {
  FrameSelection input;          // output directory by default <run directory>/surface
  surface::FieldSettings field;  // its particle spacing is taken from `input`
  int smoothing_iterations = 0;  // Taubin λ|μ iterations after marching cubes (3D)
};

/// `tide surface`: each selected frame of a run to its fluid surface, a closed triangle mesh
/// (surface_NNNNNN.ply and .obj) in 3D, smoothed if asked, the outline (outline_NNNNNN.svg and .csv) in 2D. Exit
/// code 2 with a message for a missing run, a bad frame range or an unreadable frame.
int reconstruct_surfaces(const SurfaceOptions& options);

}  // namespace tide::app
