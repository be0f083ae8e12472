#include "tide/io/recovery_writer.hpp"

#include <string>
#include <utility>
#include <vector>

namespace tide::io {
namespace {

std::vector<std::string> recovery_comments(const scene::Scene& scene, double initial_mass) {
  std::vector<std::string> comments{"TideSPH recovery of scene " + scene.source};
  if (!scene.output.recovery) return comments;
  const scene::Recovery& recovery = *scene.output.recovery;
  std::string line = "material " + scene.materials.at(recovery.material).name + " in the region " +
                     vector_text(recovery.region.min, scene.dimension) + " to " +
                     vector_text(recovery.region.max, scene.dimension) + "; initial mass ";
  append_number(line, initial_mass);
  comments.push_back(line + (scene.dimension == 2 ? " kg/m" : " kg") + "; recovery = 1 - mass / initial mass");
  return comments;
}

}  // namespace

RecoveryWriter::RecoveryWriter(std::filesystem::path file, const scene::Scene& scene, double initial_mass)
    : SeriesWriter(std::move(file), recovery_comments(scene, initial_mass), {"mass", "recovery"}) {}

}  // namespace tide::io
