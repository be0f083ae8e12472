// Rendering pieces: colour maps, the PNG file, cameras, particle splats and the font.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "particle_lattices.hpp"
#include "png_reader.hpp"
#include "tide/render/bitmap_font.hpp"
#include "tide/render/camera.hpp"
#include "tide/render/colormap.hpp"
#include "tide/render/density_heatmap.hpp"
#include "tide/render/mesh_shading.hpp"
#include "tide/render/particle_splats.hpp"
#include "tide/render/png_file.hpp"
#include "tide/surface/surface_mesh.hpp"

namespace tide::render {
namespace {

TEST(Colormap, ViridisRunsFromPurpleToYellowAndClamps) {
  const Colormap viridis("viridis");
  EXPECT_EQ(viridis.at(0), (Colour{0x44, 0x01, 0x54}));
  EXPECT_EQ(viridis.at(0.5), (Colour{0x21, 0x91, 0x8c}));
  EXPECT_EQ(viridis.at(1), (Colour{0xfd, 0xe7, 0x25}));
  EXPECT_EQ(viridis.at(-3), viridis.at(0));
  EXPECT_EQ(viridis.at(7), viridis.at(1));
  EXPECT_EQ(Colormap("gray").at(0.5), (Colour{0x80, 0x80, 0x80}));
}

TEST(Colormap, UnknownNameListsTheKnownOnes) {
  try {
    Colormap("jet");
    FAIL() << "jet is not a colour map of ours";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("gray, inferno, viridis"), std::string::npos) << error.what();
  }
}

TEST(PngFile, ReadsBackPixelForPixel) {
  Image image(37, 21, {10, 20, 30});
  for (int x = 0; x < 37; ++x) image.at(x, x % 21) = {static_cast<std::uint8_t>(7 * x), 200, 0};
  const std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "render_test.png";
  write_png(file, image);
  const Image read = testing_support::read_png(file);
  EXPECT_EQ(read.width, 37);
  EXPECT_EQ(read.height, 21);
  EXPECT_EQ(read.pixels, image.pixels);
  EXPECT_FALSE(std::filesystem::exists(file.parent_path() / ".render_test.png.tmp"));
}

// A write that fails half-way (here: a directory where its hidden temporary file must go) throws
// and leaves the picture that was there whole, as a killed render would.
TEST(PngFile, FailedRewriteKeepsTheGoodPicture) {
  const std::filesystem::path directory = std::filesystem::path(testing::TempDir()) / "png_rewrite_test";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const Image good(40, 30, {1, 2, 3});
  write_png(directory / "frame.png", good);
  std::filesystem::create_directories(directory / ".frame.png.tmp" / "blocker");
  EXPECT_THROW(write_png(directory / "frame.png", Image(40, 30, {9, 9, 9})), std::runtime_error);
  EXPECT_EQ(testing_support::read_png(directory / "frame.png").pixels, good.pixels);
  std::filesystem::remove_all(directory);
}

TEST(Camera, FramesTheBoxWithAMargin) {
  const PixelRegion region = {10, 20, 400, 300};
  const Camera flat = camera_2d({0, 0, 0}, {2, 1, 0}, region);
  const Point3 low = flat.project({0, 0, 0}), high = flat.project({2, 1, 0});
  EXPECT_NEAR(high[0] - low[0], 0.95 * 400, 1e-9);  // x fills the width first (2:1 against 4:3)
  EXPECT_NEAR(low[1] - high[1], 0.95 * 200, 1e-9);  // y up: the top is a smaller row
  EXPECT_NEAR((low[0] + high[0]) / 2, 10 + 200, 1e-9);
  const Camera solid = camera_3d({0, 0, 0}, {4, 1.5, 3}, region);
  for (int corner = 0; corner < 8; ++corner) {
    const Point3 p = solid.project({corner & 1 ? 4.0 : 0.0, corner & 2 ? 1.5 : 0.0, corner & 4 ? 3.0 : 0.0});
    EXPECT_GE(p[0], 10 - 1e-9);
    EXPECT_LE(p[0], 410 + 1e-9);
    EXPECT_GE(p[1], 20 - 1e-9);
    EXPECT_LE(p[1], 320 + 1e-9);
  }
  EXPECT_LT(solid.project({0, 0, 3})[1], solid.project({0, 0, 0})[1]);  // +z is up in the picture
}

int count_pixels(const Image& image, Colour colour) {
  int count = 0;
  for (const Colour& pixel : image.pixels) count += pixel == colour;
  return count;
}

// A disc of radius 20 pixels covers π r² = 1257 pixel centres to within its rim (2π r ≈ 126
// pixels cut either way): bound 3%. Its colour is the colour map's at the value.
TEST(ParticleSplats, TwoDimensionalParticleIsADiscOfItsRadius) {
  Image image(200, 200, {255, 255, 255});
  const Camera camera = camera_2d({-1, -1, 0}, {1, 1, 0}, {0, 0, 200, 200});
  const std::vector<double> position = {0.0, 0.0}, value = {1.0};
  const ColourScale scale{Colormap("viridis"), 0, 1};
  const double radius = 20 / camera.pixels_per_metre;
  draw_particles(image, camera, 2, position, value, scale, radius);
  EXPECT_NEAR(count_pixels(image, scale.of(1.0)), std::numbers::pi * 400, 0.03 * std::numbers::pi * 400);
}

// One point's density heat map is its kernel: W(0) = 7/(4π h²) at its pixel, and the sum over
// the pixels times a pixel's area is the kernel's integral, 1 (the point counts once), to the
// error of sampling the kernel at pixel centres (0.2% here, h = 10 pixels).
TEST(DensityHeatmap, OnePointIsItsKernelAndCountsOnce) {
  const Camera camera = camera_2d({-1, -1, 0}, {1, 1, 0}, {0, 0, 200, 200});
  const double h = 10 / camera.pixels_per_metre;
  const std::vector<double> position = {0.0, 0.0};
  const std::vector<double> density = density_on_pixels(camera, position, h);
  ASSERT_EQ(density.size(), 200U * 200U);
  double total = 0, peak = 0;
  for (const double n : density) {
    total += n;
    peak = std::max(peak, n);
  }
  const double pixel_area = 1 / (camera.pixels_per_metre * camera.pixels_per_metre);
  EXPECT_NEAR(total * pixel_area, 1, 0.005);
  // The point sits on a pixel corner: its four nearest pixel centres are half a pixel away on each axis.
  const double w0 = 7 / (4 * std::numbers::pi * h * h);
  EXPECT_NEAR(peak, w0, 0.02 * w0);
}

// In 3D the nearer sphere hides the farther one whichever is drawn first.
TEST(ParticleSplats, NearerSphereHidesTheFartherInEitherOrder) {
  const Camera camera = camera_3d({-1, -1, -1}, {1, 1, 1}, {0, 0, 100, 100});
  const Point3 towards_viewer = {-camera.forward[0] * 0.5, -camera.forward[1] * 0.5, -camera.forward[2] * 0.5};
  const std::vector<double> near_then_far = {towards_viewer[0], towards_viewer[1], towards_viewer[2], 0, 0, 0};
  const std::vector<double> far_then_near = {0, 0, 0, towards_viewer[0], towards_viewer[1], towards_viewer[2]};
  const ColourScale scale{Colormap("gray"), 0, 1};
  Image first(100, 100, {255, 0, 0}), second(100, 100, {255, 0, 0});
  draw_particles(first, camera, 3, near_then_far, std::vector<double>{1, 0}, scale, 0.2);
  draw_particles(second, camera, 3, far_then_near, std::vector<double>{0, 1}, scale, 0.2);
  EXPECT_EQ(first.pixels, second.pixels);
  const Colour centre = first.at(50, 50);
  EXPECT_EQ(centre[0], centre[1]);  // a shade of the near sphere's white, not black (the far one)
  EXPECT_GT(centre[0], 128);
}

// The reconstructed ball of radius 1 (10 particles per radius; its surface lies at the radius
// within 1%) seen by an orthographic camera is a disc of radius 1 m: measured 7076 pixels against
// π r² = 7088 (−0.17%); bound 3%, for the rim's 2π r ≈ 300 pixels cut either way. Lit from the upper left, the upper
// left of the disc is brighter than the lower right.
TEST(MeshShading, SphereCoversItsDiscAndIsLitFromTheUpperLeft) {
  const double spacing = 0.1;
  const scene::TriangleMesh ball =
      surface::reconstruct_surface(testing_support::ball_of_particles<3>(1.0, spacing), {.particle_spacing = spacing});
  const Camera camera = camera_2d({-2, -2, 0}, {2, 2, 0}, {0, 0, 200, 200});
  Image image(200, 200, {0, 0, 0});
  draw_mesh(image, camera, ball, {200, 200, 200});
  const double radius_pixels = camera.pixels_per_metre;
  const int background = count_pixels(image, {0, 0, 0});
  EXPECT_NEAR(200 * 200 - background, std::numbers::pi * radius_pixels * radius_pixels,
              0.03 * std::numbers::pi * radius_pixels * radius_pixels);
  const int offset = static_cast<int>(0.5 * radius_pixels);
  EXPECT_GT(image.at(100 - offset, 100 - offset)[0], image.at(100 + offset, 100 + offset)[0]);
}

TEST(BitmapFont, TextStaysInItsBox) {
  Image image(100, 40, {0, 0, 0});
  const std::string text = "t = 0.25 s";
  draw_text(image, 3, 5, text, {255, 255, 255}, 2);
  int lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y)[0] != 0) {
        ++lit;
        EXPECT_GE(x, 3);
        EXPECT_LT(x, 3 + text_width(text, 2));
        EXPECT_GE(y, 5);
        EXPECT_LT(y, 5 + text_height(2));
      }
  EXPECT_GT(lit, 100);
}

}  // namespace
}  // namespace tide::render
