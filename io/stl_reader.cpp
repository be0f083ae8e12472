// STL, binary and ASCII, read by TideSPH itself (the format is small; see Burns, "The StL Format",
// 1993). Binary: an 80-byte header, a little-endian uint32 triangle count, then per triangle 50
// bytes (normal, three vertices as float32, a uint16 attribute). A file whose size is not
// 84 + 50 × count and that starts with "solid" is read as ASCII. The stored normals are ignored:
// the orientation comes from the vertex order (mesh_repair.hpp).
#include <bit>
#include <cctype>
#include <charconv>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_file.hpp"

namespace tide::io {
namespace {

static_assert(std::endian::native == std::endian::little, "the binary STL reader assumes a little-endian machine");

constexpr std::size_t stl_header_bytes = 84;
constexpr std::size_t stl_triangle_bytes = 50;

scene::TriangleMesh read_binary_stl(const std::filesystem::path& file, std::string_view bytes) {
  if (bytes.size() < stl_header_bytes)
    refuse_mesh(file, "a binary STL file of at least 84 bytes", std::to_string(bytes.size()) + " bytes");
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof count);
  const std::size_t expected = stl_header_bytes + stl_triangle_bytes * std::size_t{count};
  if (bytes.size() != expected) {
    refuse_mesh(file,
                "84 + 50 × " + std::to_string(count) + " = " + std::to_string(expected) +
                    " bytes (a binary STL file of the triangle count its header declares)",
                std::to_string(bytes.size()) + " bytes" + (bytes.size() < expected ? " (truncated)" : ""));
  }
  scene::TriangleMesh mesh;
  mesh.vertices.reserve(3 * std::size_t{count});
  mesh.triangles.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + stl_header_bytes + stl_triangle_bytes * t + 12;  // after the normal
    for (int corner = 0; corner < 3; ++corner) {
      float xyz[3];
      std::memcpy(xyz, record + 12 * corner, sizeof xyz);
      mesh.vertices.push_back({xyz[0], xyz[1], xyz[2]});
    }
    mesh.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  return mesh;
}

// Whitespace-separated words with the line each is on, for messages.
class Words {
 public:
  explicit Words(std::string_view text) : text_(text) {}

  std::string_view next() {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_]))) {
      if (text_[position_] == '\n') ++line_;
      ++position_;
    }
    const std::size_t start = position_;
    while (position_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[position_]))) ++position_;
    return text_.substr(start, position_ - start);
  }

  int line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  int line_ = 1;
};

scene::TriangleMesh read_ascii_stl(const std::filesystem::path& file, std::string_view text) {
  Words words(text);
  const auto expect = [&](std::string_view word, std::string_view wanted) {
    if (word != wanted) {
      refuse_mesh(file, quoted_text(wanted) + " (ASCII STL)",
                  quoted_text(word) + " on line " + std::to_string(words.line()));
    }
  };
  const auto number = [&] {
    std::string_view word = words.next();
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc{} || end != word.data() + word.size())
      refuse_mesh(file, "a number (ASCII STL)", quoted_text(word) + " on line " + std::to_string(words.line()));
    return value;
  };
  expect(words.next(), "solid");
  scene::TriangleMesh mesh;
  std::vector<std::uint32_t> corners;
  std::string_view word = words.next();
  while (word != "facet") {  // the solid's name, possibly several words
    if (word.empty() || word == "endsolid") return mesh;
    word = words.next();
  }
  while (word == "facet") {
    expect(words.next(), "normal");
    for (int d = 0; d < 3; ++d) number();
    expect(words.next(), "outer");
    expect(words.next(), "loop");
    corners.clear();
    for (word = words.next(); word == "vertex"; word = words.next()) {
      const double x = number(), y = number(), z = number();
      corners.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
      mesh.vertices.push_back({x, y, z});
    }
    expect(word, "endloop");
    if (corners.size() < 3)
      refuse_mesh(file, "at least 3 vertices per facet",
                  std::to_string(corners.size()) + " before line " + std::to_string(words.line()));
    add_polygon(mesh, corners);
    expect(words.next(), "endfacet");
    word = words.next();
  }
  expect(word, "endsolid");
  return mesh;
}

}  // namespace

scene::TriangleMesh read_stl(const std::filesystem::path& file) {
  const std::string bytes = read_file_bytes(file);
  bool binary_size = false;
  if (bytes.size() >= stl_header_bytes) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, sizeof count);
    binary_size = bytes.size() == stl_header_bytes + stl_triangle_bytes * std::size_t{count};
  }
  if (!binary_size && bytes.starts_with("solid")) return read_ascii_stl(file, bytes);
  return read_binary_stl(file, bytes);
}

}  // namespace tide::io
