// `tide surface` as a user meets it: a run directory's frames become closed meshes (3D) or
// outlines (2D), one file pair per frame; a missing run, a bad frame range and a damaged frame are
// refused with exit code 2 and a message.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "frame_run_fixture.hpp"
#include "tide/io/mesh_reader.hpp"
#include "tide/io/mesh_repair.hpp"
#include "tide/surface/mesh_checks.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

using testing_support::CommandResult;
using testing_support::run_tide;

using SurfaceCommand = testing_support::FrameRunTest;

TEST_F(SurfaceCommand, ThreeDimensionalFramesBecomeClosedMeshes) {
  const fs::path run = write_run<3>(3);
  const CommandResult result = run_tide("surface --frames 1:2 " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("particle spacing 0.02 m"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(run / "surface" / "surface_000000.ply")) << "frame 0 is outside --frames 1:2";
  for (const char* name : {"surface_000001", "surface_000002"}) {
    for (const char* extension : {".ply", ".obj"}) {
      const scene::TriangleMesh mesh = io::read_mesh_file(run / "surface" / (std::string(name) + extension));
      EXPECT_TRUE(surface::mesh_topology(mesh).closed_and_oriented()) << name << extension;
      // The ball at 10 particles per radius, h = 1.2 Δx: measured −0.7% off the sphere's volume
      // (curvature pulls the level set in, by more at this coarser resolution than at 20 per
      // radius); bound 2%, the issue's.
      EXPECT_NEAR(io::signed_volume(mesh) / (4.0 / 3.0 * std::numbers::pi * 0.008), 1.0, 0.02) << name << extension;
    }
  }
}

// --render: the meshes, then the same frames' surfaces as pictures in RUN/render, in one command.
TEST_F(SurfaceCommand, RenderDrawsTheSurfacesToo) {
  const fs::path run = write_run<3>(2);
  const CommandResult result = run_tide("surface --render --frames 1 " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(fs::exists(run / "surface" / "surface_000001.ply"));
  EXPECT_TRUE(fs::exists(run / "render" / "frame_000001.png")) << result.output;
  EXPECT_FALSE(fs::exists(run / "render" / "frame_000000.png")) << "frame 0 is outside --frames 1";
}

TEST_F(SurfaceCommand, SmoothedMeshesStayClosedAndKeepTheirVolume) {
  const fs::path run = write_run<3>(1);
  const fs::path plain = directory_ / "plain", smoothed = directory_ / "smoothed";
  ASSERT_EQ(run_tide("surface --out " + plain.string() + " " + run.string()).exit_code, 0);
  const CommandResult result = run_tide("surface --smooth 10 --out " + smoothed.string() + " " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const scene::TriangleMesh before = io::read_mesh_file(plain / "surface_000000.ply");
  const scene::TriangleMesh after = io::read_mesh_file(smoothed / "surface_000000.ply");
  EXPECT_TRUE(surface::mesh_topology(after).closed_and_oriented());
  EXPECT_EQ(after.triangles, before.triangles);
  // As for the finer ball of surface_reconstruction_test (0.016% there); bound 0.1% here, where
  // 10 particles per radius make the bumps larger against the radius.
  EXPECT_NEAR(io::signed_volume(after) / io::signed_volume(before), 1.0, 0.001);
}

TEST_F(SurfaceCommand, TwoDimensionalFramesBecomeOutlines) {
  const fs::path run = write_run<2>(2);
  const fs::path out = directory_ / "outlines";
  const CommandResult result = run_tide("surface --out " + out.string() + " " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* name : {"outline_000000", "outline_000001"}) {
    EXPECT_TRUE(fs::exists(out / (std::string(name) + ".svg"))) << name;
    std::ifstream csv(out / (std::string(name) + ".csv"));
    std::string header;
    std::getline(csv, header);
    EXPECT_EQ(header, "loop,x,y");
  }
  EXPECT_NE(result.output.find("1 loops"), std::string::npos) << result.output;
}

TEST_F(SurfaceCommand, MissingRunIsRefused) {
  const CommandResult result = run_tide("surface " + (directory_ / "nowhere").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("no such run directory"), std::string::npos) << result.output;
}

TEST_F(SurfaceCommand, DirectoryWithoutFramesIsRefused) {
  const CommandResult result = run_tide("surface " + directory_.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("no frame files"), std::string::npos) << result.output;
}

TEST_F(SurfaceCommand, BadFrameRangesAreRefused) {
  const fs::path run = write_run<3>(2);
  for (const auto& [range, message] :
       std::vector<std::pair<std::string, std::string>>{{"3:1", "the first frame is after the last"},
                                                        {"5:9", "the run has frames 0 to 1 only"},
                                                        {"a:b", "expected A:B, A:, :B or A"},
                                                        {"1:2:3", "expected A:B, A:, :B or A"}}) {
    const CommandResult result = run_tide("surface --frames " + range + " " + run.string());
    EXPECT_EQ(result.exit_code, 2) << range << ": " << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << range << ": " << result.output;
  }
  EXPECT_FALSE(fs::exists(run / "surface" / "surface_000000.ply"));
}

TEST_F(SurfaceCommand, DamagedFrameIsRefused) {
  const fs::path run = write_run<3>(2);
  std::ofstream(run / "frames_000001.h5", std::ios::trunc) << "not HDF5";
  const CommandResult result = run_tide("surface --frames 1 " + run.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("frames_000001.h5"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace tide
