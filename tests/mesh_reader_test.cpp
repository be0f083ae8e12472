// The mesh readers on tiny files written here: the unit cube as ASCII STL, binary STL, PLY (ascii
// and binary) and OBJ reads, once repaired, as the same 12 outward triangles enclosing volume 1;
// broken files are refused with the file's name and what is wrong.

#include "tide/io/mesh_reader.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mesh_shapes.hpp"
#include "tide/io/mesh_repair.hpp"

namespace tide {
namespace {

namespace fs = std::filesystem;
using Corner = std::array<double, 3>;
using Triangle = std::array<Corner, 3>;

class MeshReader : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("tide_mesh_reader_" + std::to_string(::getpid()));
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  fs::path write(const std::string& name, const std::string& bytes) const {
    const fs::path file = directory_ / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }

  fs::path directory_;
};

const scene::TriangleMesh cube = test::box_mesh({0, 0, 0}, {1, 1, 1});

// Triangles by their corners' coordinates, each started at its smallest corner (the orientation
// kept), sorted: equal for meshes that differ only in vertex numbering and triangle order.
std::vector<Triangle> canonical(const scene::TriangleMesh& mesh) {
  std::vector<Triangle> triangles;
  for (const auto& t : mesh.triangles) {
    Triangle corners{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    triangles.push_back(corners);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

std::string ascii_stl(const scene::TriangleMesh& mesh) {
  std::string text = "solid cube made by hand\n";
  for (const auto& t : mesh.triangles) {
    text += "  facet normal 0 0 0\n    outer loop\n";
    for (const auto v : t) {
      const auto& x = mesh.vertices[v];
      text += "      vertex " + std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]) + "\n";
    }
    text += "    endloop\n  endfacet\n";
  }
  return text + "endsolid cube\n";
}

template <class T>
void append(std::string& bytes, T value) {
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  bytes.append(raw, sizeof value);
}

std::string binary_stl(const scene::TriangleMesh& mesh) {
  std::string bytes(80, ' ');
  append(bytes, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) append(bytes, 0.0f);
    for (const auto v : t)
      for (const double x : mesh.vertices[v]) append(bytes, static_cast<float>(x));
    append(bytes, std::uint16_t{0});
  }
  return bytes;
}

// The cube's six faces as quads (split into triangles by the reader), with an extra vertex
// property and an extra element the reader must skip.
std::string ply_header(const std::string& format, std::size_t vertices = 8) {
  return "ply\nformat " + format + " 1.0\ncomment by hand\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
         "element face 6\nproperty list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\n"
         "property int vertex2\nend_header\n";
}

const std::vector<std::array<std::uint32_t, 4>> cube_quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                              {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

std::string ascii_ply() {
  std::string text = ply_header("ascii");
  for (const auto& x : cube.vertices)
    text += std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]) + " 255\n";
  for (const auto& q : cube_quads)
    text += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
            std::to_string(q[3]) + "\n";
  return text + "0 1\n";
}

std::string binary_ply() {
  std::string bytes = ply_header("binary_little_endian");
  for (const auto& x : cube.vertices) {
    for (const double c : x) append(bytes, static_cast<float>(c));
    append(bytes, std::uint8_t{255});
  }
  for (const auto& q : cube_quads) {
    append(bytes, std::uint8_t{4});
    for (const auto v : q) append(bytes, static_cast<std::int32_t>(v));
  }
  append(bytes, std::int32_t{0});
  append(bytes, std::int32_t{1});
  return bytes;
}

std::string obj() {
  std::string text = "# the unit cube\no cube\n";
  for (const auto& x : cube.vertices)
    text += "v " + std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]) + "\n";
  for (const auto& q : cube_quads)
    text += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " +
            std::to_string(q[3] + 1) + "\n";
  return text;
}

std::string refusal(const fs::path& file) {
  try {
    io::read_mesh_file(file);
  } catch (const scene::SceneError& error) {
    return error.what();
  }
  return "no error";
}

TEST_F(MeshReader, EveryFormatGivesTheSameCube) {
  const std::vector<fs::path> files = {write("cube_ascii.stl", ascii_stl(cube)),
                                       write("cube_binary.STL", binary_stl(cube)), write("cube_ascii.ply", ascii_ply()),
                                       write("cube_binary.ply", binary_ply()), write("cube.obj", obj())};
  scene::TriangleMesh expected = cube;
  io::repair_mesh(expected, "cube");
  for (const fs::path& file : files) {
    scene::TriangleMesh mesh = io::read_mesh_file(file);
    // STL keeps three corners per triangle; the others share the cube's 8 vertices.
    EXPECT_EQ(mesh.vertices.size(), file.extension() == ".ply" || file.extension() == ".obj" ? 8u : 36u) << file;
    EXPECT_EQ(mesh.triangles.size(), 12u) << file;
    io::repair_mesh(mesh, file);
    EXPECT_EQ(mesh.vertices.size(), 8u) << file;
    EXPECT_EQ(canonical(mesh), canonical(expected)) << file;
    EXPECT_DOUBLE_EQ(io::signed_volume(mesh), 1.0) << file;  // terms of k/6 each: within 4 ulps
  }
}

TEST_F(MeshReader, TruncatedBinaryStlIsRefused) {
  const std::string bytes = binary_stl(cube);
  const std::string message = refusal(write("short.stl", bytes.substr(0, bytes.size() - 10)));
  EXPECT_NE(message.find("short.stl"), std::string::npos) << message;
  EXPECT_NE(message.find("684 bytes"), std::string::npos) << message;  // 84 + 50 × 12
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST_F(MeshReader, HugeDeclaredCountsAreRefusedBeforeAllocating) {
  std::string stl = binary_stl(cube);
  const std::uint32_t huge = 4'000'000'000u;
  std::memcpy(stl.data() + 80, &huge, sizeof huge);
  EXPECT_NE(refusal(write("huge.stl", stl)).find("truncated"), std::string::npos);
  const std::string ply = ply_header("binary_little_endian", 2'000'000'000) + "\x01\x02";
  const std::string message = refusal(write("huge.ply", ply));
  EXPECT_NE(message.find("2000000000 vertex elements"), std::string::npos) << message;
}

TEST_F(MeshReader, IndicesOutOfRangeAreRefused) {
  std::string ply = ascii_ply();
  ply.replace(ply.find("4 0 2 3 1"), 9, "4 0 2 3 9");
  std::string message = refusal(write("bad_index.ply", ply));
  EXPECT_NE(message.find("bad_index.ply"), std::string::npos) << message;
  EXPECT_NE(message.find("triangle 1 with vertex index 9"), std::string::npos) << message;
  message = refusal(write("bad_index.obj", obj() + "f 1 2 99\n"));
  EXPECT_NE(message.find("vertex 99"), std::string::npos) << message;
}

TEST_F(MeshReader, NonFiniteCoordinatesAreRefused) {
  std::string stl = ascii_stl(cube);
  stl.replace(stl.find("vertex ") + 7, 8, "nan");
  const std::string message = refusal(write("nan.stl", stl));
  EXPECT_NE(message.find("non-finite coordinate"), std::string::npos) << message;
}

TEST_F(MeshReader, TruncatedTextAndUnknownFilesAreRefused) {
  const std::string ply = ascii_ply();
  EXPECT_NE(refusal(write("cut.ply", ply.substr(0, ply.size() - 8))).find("truncated"), std::string::npos);
  const std::string stl = ascii_stl(cube);
  EXPECT_NE(refusal(write("cut.stl", stl.substr(0, stl.size() / 2))).find("ASCII STL"), std::string::npos);
  EXPECT_NE(refusal(write("cube.off", "OFF")).find("the extension \".off\""), std::string::npos);
  EXPECT_NE(refusal(directory_ / "absent.stl").find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace tide
