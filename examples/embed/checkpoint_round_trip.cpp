// A checkpoint round trip through the installed package: a small 2D dam break runs 40 steps
// straight, and again as 20 steps, a checkpoint file, a fresh simulation restored from it and 20
// more; the two must end with the same bits in every field.

#include "checkpoint_round_trip.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "tide/core/scene.hpp"
#include "tide/io/checkpoint_file.hpp"
#include "tide/solvers/simulation.hpp"

namespace {

// A 0.2 x 0.4 m water column in a 0.6 x 0.5 m tank, 1 cm spacing: 800 particles.
tide::scene::Scene dam_break() {
  tide::scene::Scene s;
  s.source = "embedded dam break";
  s.particle_spacing = 0.01;
  s.smoothing_ratio = 1.7;
  s.materials.push_back({"water", 1000, 1e-6, std::nullopt, 2.0});
  s.fluid.push_back({0, tide::scene::Box{{0, 0, 0}, {0.2, 0.4, 0}}});
  s.walls.container = tide::scene::Container{tide::scene::Box{{0, 0, 0}, {0.6, 0.5, 0}}, true};
  s.domain.box = {{-0.03, -0.03, 0}, {0.63, 1.0, 0}};
  return s;
}

bool same_state(const tide::StateArchive& a, const tide::StateArchive& b) {
  if (a.all_reals().size() != b.all_reals().size()) return false;
  for (const auto& [path, values] : a.all_reals()) {
    const auto other = b.all_reals().find(path);
    if (other == b.all_reals().end() || other->second.size() != values.size() ||
        (!values.empty() &&
         std::memcmp(values.data(), other->second.data(), values.size() * sizeof(tide::Real)) != 0)) {
      std::printf("  %s differs after the resume\n", path.c_str());
      return false;
    }
  }
  return true;
}

tide::StateArchive state_of(const tide::Simulation<2>& simulation) {
  tide::StateArchive archive;
  simulation.save(archive);
  return archive;
}

}  // namespace

bool checkpoint_round_trip() {
  const tide::scene::Scene scene = dam_break();
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "tide_embed_checkpoint.h5";
  const tide::io::CheckpointIdentity identity{
      tide::io::checkpoint_format_version, "embedded dam break", TIDE_REAL_NAME, 2, {}};

  const auto straight = tide::make_simulation<2>(scene);
  for (int k = 0; k < 40; ++k) straight->step();

  const auto first = tide::make_simulation<2>(scene);
  for (int k = 0; k < 20; ++k) first->step();
  tide::io::write_checkpoint(file, identity, first->step_count(), first->time(), state_of(*first));
  const auto resumed = tide::make_simulation<2>(scene);
  resumed->restore(tide::io::read_checkpoint(file, identity));
  for (int k = 0; k < 20; ++k) resumed->step();
  std::filesystem::remove(file);

  const bool same = same_state(state_of(*straight), state_of(*resumed));
  std::printf("  checkpoint at step 20 of 40, %zu particles: the resumed run %s\n", straight->fluid().size(),
              same ? "ends with the same bits" : "DIFFERS");
  return same;
}
