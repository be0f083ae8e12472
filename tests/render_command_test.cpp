// `tide render` as a user meets it: a run's frames become PNG pictures of the requested size with
// the particles in the colour map's colours; bad options are refused with exit code 2.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "frame_run_fixture.hpp"
#include "png_reader.hpp"
#include "tide/render/colormap.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

using testing_support::CommandResult;
using testing_support::run_tide;

using RenderCommand = testing_support::FrameRunTest;

/// Pixels of `colour` left of the colour bar (which takes the rightmost 170 pixels).
int count_plot_pixels(const render::Image& image, render::Colour colour) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width - 170; ++x) count += image.at(x, y) == colour;
  return count;
}

// The disc's particles carry |v| from 0.014 m/s (next to the centre) to 0.19 m/s (at the rim):
// flat 2D discs show the colour map's two ends, and the picture has the size asked for. An MP4
// only where ffmpeg is installed.
TEST_F(RenderCommand, TwoDimensionalFramesBecomePictures) {
  const fs::path run = write_run<2>(3);
  const CommandResult result = run_tide("render --size 640x360 --colormap inferno " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* name : {"frame_000000.png", "frame_000001.png", "frame_000002.png"}) {
    const render::Image image = testing_support::read_png(run / "render" / name);
    EXPECT_EQ(image.width, 640);
    EXPECT_EQ(image.height, 360);
    const render::Colormap inferno("inferno");
    EXPECT_GT(count_plot_pixels(image, inferno.at(0)), 0) << name;  // the particles next to the centre
    EXPECT_GT(count_plot_pixels(image, inferno.at(1)), 0) << name;  // the rim
  }
  const bool movie =
      result.output.find("movie.mp4") != std::string::npos && result.output.find("no MP4") == std::string::npos;
  EXPECT_EQ(movie, fs::exists(run / "render" / "movie.mp4")) << result.output;
}

TEST_F(RenderCommand, ThreeDimensionalFramesBecomePictures) {
  const fs::path run = write_run<3>(2);
  const CommandResult result =
      run_tide("render --frames 1 --out " + (directory_ / "pictures").string() + " " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_FALSE(fs::exists(directory_ / "pictures" / "frame_000000.png"));
  const render::Image image = testing_support::read_png(directory_ / "pictures" / "frame_000001.png");
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
}

// --surface draws the reconstructed surface, one colour shaded: the ball's disc of water-blue
// shades, and no colour bar.
TEST_F(RenderCommand, SurfaceOfAThreeDimensionalRunIsDrawn) {
  const fs::path run = write_run<3>(1);
  const CommandResult result = run_tide("render --surface " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const render::Image image = testing_support::read_png(run / "render" / "frame_000000.png");
  int blue = 0;
  for (const render::Colour& pixel : image.pixels) blue += pixel[2] > pixel[0] + 40;
  EXPECT_GT(blue, 1000);
  const CommandResult flat = run_tide("render --surface " + write_run<2>(1).string());
  EXPECT_EQ(flat.exit_code, 2) << flat.output;
  EXPECT_NE(flat.output.find("--surface draws the surfaces of 3D runs"), std::string::npos) << flat.output;
}

// --heatmap colours the whole floor of a 2D run by its points' density: every pixel of the plot
// region coloured (the empty floor at the scale's bottom), a colour bar; refused for a 3D run.
TEST_F(RenderCommand, HeatmapOfATwoDimensionalRunColoursTheFloor) {
  const fs::path run = write_run<2>(1);
  const CommandResult result = run_tide("render --heatmap --size 640x360 " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("density heat map"), std::string::npos) << result.output;
  const render::Image image = testing_support::read_png(run / "render" / "frame_000000.png");
  const render::Colormap viridis("viridis");
  int floor = 0, crowded = 0;
  for (const render::Colour& pixel : image.pixels) {
    floor += pixel == viridis.at(0);
    crowded += pixel != viridis.at(0) && pixel != render::Colour{0xff, 0xff, 0xff};
  }
  EXPECT_GT(floor, 1000);
  EXPECT_GT(crowded, 1000);
  const CommandResult solid = run_tide("render --heatmap " + write_run<3>(1).string());
  EXPECT_EQ(solid.exit_code, 2) << solid.output;
  EXPECT_NE(solid.output.find("--heatmap draws the density of a 2D run"), std::string::npos) << solid.output;
}

TEST_F(RenderCommand, BadOptionsAreRefused) {
  const fs::path run = write_run<2>(1);
  for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
           {"--size 100", "expected WxH"},
           {"--size 20x20", "from 320x240 to 8192x8192"},
           {"--colormap jet", "unknown colour map 'jet'"},
           {"--field vorticity", "no field 'vorticity' (the frame has position, velocity)"},
           {"--frames 4:", "the run has frames 0 to 0 only"}}) {
    const CommandResult result = run_tide("render " + options + " " + run.string());
    EXPECT_EQ(result.exit_code, 2) << options << ": " << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << options << ": " << result.output;
  }
  const CommandResult missing = run_tide("render " + (directory_ / "nowhere").string());
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_FALSE(fs::exists(run / "render" / "frame_000000.png"));
}

}  // namespace
}  // namespace tide
