#pragma once

// A run directory written without a simulation, for the tests of the commands that read runs
// (tide surface, tide render): a fresh temporary directory per test and frames of a ball (disc) of
// particles that moves along x.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "particle_lattices.hpp"
#include "run_command.hpp"
#include "tide/io/frame_writer.hpp"

namespace tide::testing_support {

inline CommandResult run_tide(const std::string& arguments) { return run_command(TIDE_COMMAND, arguments); }

class FrameRunTest : public testing::Test {
 protected:
  void SetUp() override {
    const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
    directory_ = std::filesystem::temp_directory_path() /
                 (std::string(test->test_suite_name()) + "_" + std::string(test->name()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  /// `frames` frames of a ball (disc) of radius 0.2 m, Δx = 0.02 m, that moves by its radius along
  /// x per frame; each particle's velocity is its offset from the ball's centre (|v| = distance).
  template <int D>
  std::filesystem::path write_run(int frames) {
    const double radius = 0.2, spacing = radius / 10;
    const std::vector<double> lattice = ball_of_particles<D>(radius, spacing);
    ParticleSet<D> particles;
    particles.append(lattice.size() / D);
    const VectorField velocity_field = particles.add_vector("velocity");
    io::FrameWriter<D> writer(directory_ / "run", {"position", "velocity"});
    for (int frame = 0; frame < frames; ++frame) {
      const VectorView<D> position = particles[particles.position()];
      const VectorView<D> velocity = particles[velocity_field];
      for (std::size_t i = 0; i < particles.size(); ++i) {
        for (int d = 0; d < D; ++d) {
          position.component[d][i] = static_cast<Real>(lattice[i * D + d] + (d == 0) * frame * radius);
          velocity.component[d][i] = static_cast<Real>(lattice[i * D + d]);
        }
      }
      writer.write(particles, 0.1 * frame, static_cast<std::uint64_t>(frame));
    }
    return directory_ / "run";
  }

  std::filesystem::path directory_;
};

}  // namespace tide::testing_support
