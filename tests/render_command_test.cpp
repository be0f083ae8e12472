// `tide render` as a user meets it: a run's frames become PNG pictures of the requested size with
// the particles in the colour map's colours; bad options are refused with exit code 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "frame_run_fixture.hpp"
#include "png_reader.hpp"
#include "tide/io/frame_writer.hpp"
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

/// Writes `frames` frames of the wall run `stem` into `run` as tide run does: the points
/// `positions` (row-major, D a point), moved along x by `shift` m per frame. One frame is how a
/// run writes its fixed walls.
template <int D>
void write_walls(const fs::path& run, const std::string& stem, const std::vector<double>& positions, int frames,
                 double shift) {
  ParticleSet<D> particles;
  particles.append(positions.size() / D);
  io::FrameWriter<D> writer(run, {"position"}, stem);
  for (int frame = 0; frame < frames; ++frame) {
    const VectorView<D> position = particles[particles.position()];
    for (std::size_t i = 0; i < particles.size(); ++i)
      for (int d = 0; d < D; ++d)
        position.component[d][i] = static_cast<Real>(positions[i * D + d] + (d == 0) * frame * shift);
    writer.write(particles, 0.1 * frame, static_cast<std::uint64_t>(frame));
  }
}

/// The points of a square grid of spacing 0.02 m on a plane: `fixed` coordinate `at`, the other
/// two (3D) or the other one (2D) from −`half` to `half`.
template <int D>
std::vector<double> wall_plane(int fixed, double at, double half) {
  std::vector<double> points;
  const int steps = static_cast<int>(std::lround(2 * half / 0.02));
  for (int a = 0; a <= steps; ++a) {
    for (int b = 0; b <= (D == 3 ? steps : 0); ++b) {
      const double free[2] = {-half + 0.02 * a, -half + 0.02 * b};
      std::array<double, 3> point{};
      for (int d = 0, next = 0; d < D; ++d) point[static_cast<std::size_t>(d)] = d == fixed ? at : free[next++];
      points.insert(points.end(), point.begin(), point.begin() + D);
    }
  }
  return points;
}

/// The mean picture column of the pixels of `colour` (left of the colour bar), and their count.
std::pair<double, int> pixels_of(const render::Image& image, render::Colour colour) {
  double column = 0;
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width - 170; ++x)
      if (image.at(x, y) == colour) column += x, ++count;
  return {count > 0 ? column / count : 0.0, count};
}

/// Shaded grey pixels (3D walls: equal channels; the wall grey 0x9a at least 0.35 of it lit, so
/// above the labels' ink 0x20, and below the white background).
int grey_pixels(const render::Image& image) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width - 170; ++x) {
      const render::Colour& p = image.at(x, y);
      count += p[0] == p[1] && p[1] == p[2] && p[0] > 0x20 && p[0] < 0xff;
    }
  return count;
}

// A 2D run with a fixed wall (one frame, as tide run writes walls_000000.h5) under the disc and a
// body (named in bodies.csv) above it that moves 0.2 m right per frame: the wall in grey
// (0x9a9a9a) in every picture, the body in brown (0x8b5a2b) further right in the later frame (by
// 0.4 m of the 1.3 m the picture spans; measured 0.4 m × 440 / 1.3 ≈ 135 pixels at 640 × 360).
TEST_F(RenderCommand, WallsAndBodiesAreDrawnIn2D) {
  const fs::path run = write_run<2>(3);
  write_walls<2>(run, "walls", wall_plane<2>(1, -0.3, 0.5), 1, 0.0);
  std::vector<double> body;
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b) body.insert(body.end(), {-0.04 + 0.02 * a, 0.3 + 0.02 * b});
  write_walls<2>(run, "walls_obstacles_0", body, 3, 0.2);
  {
    std::ofstream csv(run / "bodies.csv");
    csv << "# TideSPH rigid bodies\ntime,walls.obstacles[0].x,walls.obstacles[0].y\n0,0,0.34\n";
  }
  const CommandResult result = run_tide("render --size 640x360 " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const render::Colour grey = {0x9a, 0x9a, 0x9a}, brown = {0x8b, 0x5a, 0x2b};
  const render::Image first = testing_support::read_png(run / "render" / "frame_000000.png");
  const render::Image last = testing_support::read_png(run / "render" / "frame_000002.png");
  EXPECT_GT(pixels_of(first, grey).second, 100);
  EXPECT_GT(pixels_of(last, grey).second, 100);
  const auto [body_first, count_first] = pixels_of(first, brown);
  const auto [body_last, count_last] = pixels_of(last, brown);
  EXPECT_GT(count_first, 1000);                              // 25 particles' discs of 0.02 m (≈ 7 pixels) across
  EXPECT_NEAR(count_last, count_first, 0.01 * count_first);  // measured 1320 and 1317: other sub-pixel places
  EXPECT_GT(body_last - body_first, 100.0);
}

// In 3D the walls are shaded grey spheres, those beyond the fluid's box only on sides facing the
// camera (which looks from +x, −y, +z) left out: a floor under the ball is drawn (beyond the box
// below, a side facing away, even where it reaches beyond it in +x), a wall at x = 0.4 m in front
// of the ball and within its box along y and z is not (and the ball behind it shows).
TEST_F(RenderCommand, WallsIn3DLeaveOutThoseInFrontOfTheFluid) {
  const fs::path floor_run = write_run<3>(1);
  write_walls<3>(floor_run, "walls", wall_plane<3>(2, -0.3, 0.4), 1, 0.0);
  ASSERT_EQ(run_tide("render --size 640x360 " + floor_run.string()).exit_code, 0);
  EXPECT_GT(grey_pixels(testing_support::read_png(floor_run / "render" / "frame_000000.png")), 1000);

  const fs::path near_run = directory_ / "near";
  fs::rename(floor_run, near_run);
  for (const auto& entry : fs::directory_iterator(near_run))
    if (entry.path().filename().string().rfind("walls", 0) == 0 || entry.is_directory()) fs::remove_all(entry.path());
  write_walls<3>(near_run, "walls", wall_plane<3>(0, 0.4, 0.16), 1, 0.0);
  ASSERT_EQ(run_tide("render --size 640x360 " + near_run.string()).exit_code, 0);
  const render::Image image = testing_support::read_png(near_run / "render" / "frame_000000.png");
  EXPECT_EQ(grey_pixels(image), 0);
  int ball = 0;  // pixels of unequal channels: the shaded spheres of the ball
  for (const render::Colour& p : image.pixels) ball += !(p[0] == p[1] && p[1] == p[2]);
  EXPECT_GT(ball, 1000);
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
