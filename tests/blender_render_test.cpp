// The Blender route (docs/rendering.md): scripts/blender_render_surfaces.py renders a mesh that
// tide surface wrote, headless, with Cycles on the CPU. Skipped, saying why, where Blender is not
// installed.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "particle_lattices.hpp"
#include "png_reader.hpp"
#include "run_command.hpp"
#include "tide/surface/surface_files.hpp"
#include "tide/surface/surface_mesh.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

/// Blue minus red: the water material is light blue, the floor and sky about grey.
int blueness(const render::Colour& colour) { return int(colour[2]) - int(colour[0]); }

TEST(BlenderRoute, RendersASurfaceMeshHeadless) {
  if (testing_support::run_command("command -v", "blender").exit_code != 0)
    GTEST_SKIP() << "blender is not installed (Debian: apt-get install blender), so the Blender route is not tried";
  const fs::path directory = fs::temp_directory_path() / "blender_render_test";
  fs::remove_all(directory);
  fs::create_directories(directory / "surface");
  const double spacing = 0.05;
  surface::write_ply(
      directory / "surface" / "surface_000003.ply",
      surface::reconstruct_surface(testing_support::ball_of_particles<3>(0.5, spacing), {.particle_spacing = spacing}));
  std::ostringstream arguments;  // GCC 12 warns falsely (-Wstringop-overflow) on a + chain of these
  arguments << "-b --python " << TIDE_BLENDER_SCRIPT << " -- " << (directory / "surface").string() << ' '
            << (directory / "pictures").string() << " --size 160x90 --samples 4";
  const testing_support::CommandResult result = testing_support::run_command("blender", arguments.str());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const render::Image image = testing_support::read_png(directory / "pictures" / "blender_000003.png");
  EXPECT_EQ(image.width, 160);
  EXPECT_EQ(image.height, 90);
  // The ball fills the middle of the picture, the floor and sky its corner.
  EXPECT_GT(blueness(image.at(80, 45)), blueness(image.at(2, 2)) + 20)
      << "centre " << int(image.at(80, 45)[0]) << "," << int(image.at(80, 45)[1]) << "," << int(image.at(80, 45)[2])
      << " corner " << int(image.at(2, 2)[0]) << "," << int(image.at(2, 2)[1]) << "," << int(image.at(2, 2)[2]);
  fs::remove_all(directory);
}

}  // namespace
}  // namespace tide
