// Mesh obstacles in scene files: the file is found beside the scene, read once, repaired and
// placed (scale × units, rotation, translation); bad mesh keys and bad mesh files fail at their
// key path, naming the mesh file and the reason.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tide/io/scene_reader.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;

// A cube of side 10 (file units) from the origin, its faces as quads; `faces` of the 6 kept.
std::string cube_obj(int faces = 6) {
  std::string text;
  for (int k = 0; k < 8; ++k)
    text += "v " + std::to_string((k & 1) * 10) + " " + std::to_string((k & 2) * 5) + " " +
            std::to_string((k & 4) * 5 / 2) + "\n";
  const char* quads[] = {"f 1 3 4 2\n", "f 5 6 8 7\n", "f 1 2 6 5\n", "f 3 7 8 4\n", "f 1 5 7 3\n", "f 2 4 8 6\n"};
  for (int f = 0; f < faces; ++f) text += quads[f];
  return text;
}

class MeshScene : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("tide_mesh_scene_" + std::to_string(::getpid()));
    fs::create_directories(directory_ / "meshes");
    std::ofstream(directory_ / "meshes" / "cube.obj") << cube_obj();
    std::ofstream(directory_ / "meshes" / "open.obj") << cube_obj(5);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // A 3D tank with one mesh obstacle whose "mesh" object is `mesh`.
  fs::path scene(const std::string& mesh) const {
    const fs::path file = directory_ / "tank.json";
    std::ofstream(file) << R"({"dimension": 3, "particle_spacing": 0.02,
      "materials": [{"name": "water", "max_speed": 1}], "time": {"end": 0.1},
      "fluid": [{"material": "water", "box": {"min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}}],
      "walls": {"container": {"min": [0, 0, 0], "max": [1, 1, 1]}, "obstacles": [{"mesh": )"
                        << mesh << R"(}]}})";
    return file;
  }

  scene::SceneError refusal(const std::string& mesh) const {
    try {
      io::read_scene_file(scene(mesh));
    } catch (const scene::SceneError& error) {
      return error;
    }
    return scene::SceneError("", "", "an error", "none");
  }

  fs::path directory_;
};

TEST_F(MeshScene, MeshIsReadBesideTheSceneAndPlaced) {
  const scene::Scene s = io::read_scene_file(scene(
      R"({"file": "meshes/cube.obj", "scale": 2, "units": "cm", "rotation": {"axis": [0, 0, 1], "degrees": 90},
          "translation": [0.5, 0.3, 0.1]})"));
  const auto& mesh = std::get<scene::Mesh>(s.walls.obstacles.at(0).shape);
  EXPECT_EQ(mesh.surface->triangles.size(), 12u);
  // 10 cm × 2 = 0.2 m on a side; a quarter turn about z takes [0, 0.2] on x to [−0.2, 0] on y.
  const scene::Vec lo{0.5, 0.3, 0.1}, hi{0.7, 0.5, 0.3};
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(mesh.bounds.min[d], lo[d] - (d == 0 ? 0.2 : 0), 1e-15) << d;
    EXPECT_NEAR(mesh.bounds.max[d], hi[d] - (d == 0 ? 0.2 : 0), 1e-15) << d;
  }
}

TEST_F(MeshScene, MissingFileFailsAtItsKey) {
  const scene::SceneError error = refusal(R"({"file": "meshes/none.stl"})");
  EXPECT_EQ(error.key_path(), "/walls/obstacles/0/mesh/file");
  EXPECT_NE(std::string(error.what()).find("none.stl: expected a mesh file, got no such file"), std::string::npos)
      << error.what();
}

TEST_F(MeshScene, OpenMeshFailsWithTheTriangle) {
  const scene::SceneError error = refusal(R"({"file": "meshes/open.obj"})");
  EXPECT_EQ(error.key_path(), "/walls/obstacles/0/mesh/file");
  const std::string message = error.what();
  EXPECT_NE(message.find("open.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("triangle 1 has an open edge"), std::string::npos) << message;
}

TEST_F(MeshScene, BadMeshKeysFailAtTheirPaths) {
  EXPECT_EQ(refusal(R"({"scale": 2})").key_path(), "/walls/obstacles/0/mesh/file");
  EXPECT_EQ(refusal(R"({"file": "meshes/cube.obj", "units": "in"})").key_path(), "/walls/obstacles/0/mesh/units");
  EXPECT_EQ(refusal(R"({"file": "meshes/cube.obj", "scale": 0})").key_path(), "/walls/obstacles/0/mesh/scale");
  EXPECT_EQ(refusal(R"({"file": "meshes/cube.obj", "rotation": {"axis": [0, 0, 0]}})").key_path(),
            "/walls/obstacles/0/mesh/rotation/axis");
  EXPECT_EQ(refusal(R"({"file": "meshes/cube.obj", "translation": [1, 2]})").key_path(),
            "/walls/obstacles/0/mesh/translation");
  EXPECT_EQ(refusal(R"({"file": "meshes/cube.obj", "colour": "red"})").key_path(), "/walls/obstacles/0/mesh/colour");
}

TEST_F(MeshScene, MeshOutsideTheDomainIsRefused) {
  const scene::SceneError error = refusal(R"({"file": "meshes/cube.obj", "translation": [0.95, 0, 0]})");
  EXPECT_EQ(error.key_path(), "/walls/obstacles/0/mesh");
  EXPECT_NE(std::string(error.what()).find("inside the domain"), std::string::npos) << error.what();
}

}  // namespace
}  // namespace tide
