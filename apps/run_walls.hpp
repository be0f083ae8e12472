#pragma once

// The walls and bodies a run wrote beside its frames (docs/output.md): the fixed walls once
// (walls_000000.h5, ...), each moving obstacle and body at every frame (walls_obstacles_2_NNNNNN.h5),
// the bodies named by bodies.csv's columns. What tide render draws under and around the fluid.

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace tide::app {

/// The wall and body particles at one frame, row-major positions of the run's dimension.
struct WallParticles {
  std::vector<double> walls;
  std::vector<double> bodies;
};

class RunWalls {
 public:
  /// Every run of wall frames in `run_directory` (files <stem>_NNNNNN.h5 other than the fluid's).
  explicit RunWalls(const std::filesystem::path& run_directory);

  bool empty() const { return series_.empty(); }

  /// Each run's frame with the largest number up to `frame`: a moving wall's or body's own frame
  /// `frame`, the fixed walls' only frame 0. std::runtime_error for a file that cannot be read.
  WallParticles at(std::size_t frame) const;

 private:
  struct Series {
    std::vector<std::pair<std::size_t, std::filesystem::path>> frames;  // ascending numbers
    bool body = false;
  };
  std::vector<Series> series_;  // by stem
};

}  // namespace tide::app
