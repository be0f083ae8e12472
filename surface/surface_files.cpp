#include "tide/surface/surface_files.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "tide/io/atomic_file.hpp"

namespace tide::surface {
namespace {

static_assert(std::endian::native == std::endian::little, "PLY files are written as the machine's bytes");

/// The shortest text that reads back as the same double.
void append_number(std::string& text, double value) {
  char digits[32];
  const auto result = std::to_chars(digits, digits + sizeof digits, value);
  text.append(digits, result.ptr);
}

void write_bytes(const std::filesystem::path& path, const std::string& header, const std::string& body) {
  io::replace_atomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    out.close();
    if (!out) throw std::runtime_error(temporary.string() + ": cannot write the file");
  });
}

template <class T>
void append_binary(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

}  // namespace

void write_ply(const std::filesystem::path& path, const scene::TriangleMesh& mesh) {
  if (mesh.vertices.size() > std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw std::runtime_error(path.string() + ": more vertices than a PLY int index holds");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment TideSPH fluid surface\nelement vertex " +
      std::to_string(mesh.vertices.size()) + "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body;
  body.reserve(mesh.vertices.size() * 12 + mesh.triangles.size() * 13);
  for (const auto& vertex : mesh.vertices)
    for (const double coordinate : vertex) append_binary(body, static_cast<float>(coordinate));
  for (const auto& triangle : mesh.triangles) {
    append_binary(body, std::uint8_t{3});
    for (const std::uint32_t index : triangle) append_binary(body, static_cast<std::int32_t>(index));
  }
  write_bytes(path, header, body);
}

void write_obj(const std::filesystem::path& path, const scene::TriangleMesh& mesh) {
  std::string body;
  body.reserve(mesh.vertices.size() * 60 + mesh.triangles.size() * 24);
  for (const auto& vertex : mesh.vertices) {
    body += 'v';
    for (const double coordinate : vertex) {
      body += ' ';
      append_number(body, coordinate);
    }
    body += '\n';
  }
  for (const auto& triangle : mesh.triangles)
    body += "f " + std::to_string(triangle[0] + 1) + ' ' + std::to_string(triangle[1] + 1) + ' ' +
            std::to_string(triangle[2] + 1) + '\n';
  write_bytes(path, "# TideSPH fluid surface\n", body);
}

void write_outline_csv(const std::filesystem::path& path, const Outline& outline) {
  std::string body;
  for (std::size_t loop = 0; loop < outline.loops.size(); ++loop) {
    for (const auto& point : outline.loops[loop]) {
      body += std::to_string(loop) + ',';
      append_number(body, point[0]);
      body += ',';
      append_number(body, point[1]);
      body += '\n';
    }
  }
  write_bytes(path, "loop,x,y\n", body);
}

void write_outline_svg(const std::filesystem::path& path, const Outline& outline, int width) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double lowest[2] = {infinity, infinity}, highest[2] = {-infinity, -infinity};
  for (const auto& loop : outline.loops)
    for (const auto& point : loop)
      for (int d = 0; d < 2; ++d) {
        lowest[d] = std::min(lowest[d], point[d]);
        highest[d] = std::max(highest[d], point[d]);
      }
  if (outline.loops.empty()) lowest[0] = lowest[1] = 0, highest[0] = highest[1] = 1;
  const double span_x = std::max(highest[0] - lowest[0], 1e-12), span_y = std::max(highest[1] - lowest[1], 1e-12);
  const double scale = width / span_x;
  const int height = std::max(1, static_cast<int>(std::lround(span_y * scale)));
  std::string path_data;
  for (const auto& loop : outline.loops) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      path_data += k == 0 ? 'M' : 'L';
      append_number(path_data, (loop[k][0] - lowest[0]) * scale);
      path_data += ',';
      append_number(path_data, (highest[1] - loop[k][1]) * scale);
    }
    path_data += 'Z';
  }
  const std::string header =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
      std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
      ' ' + std::to_string(height) + "\">\n";
  write_bytes(path, header,
              "  <path fill=\"#6fa8dc\" fill-rule=\"evenodd\" stroke=\"#0b3d91\" stroke-width=\"1\" d=\"" + path_data +
                  "\"/>\n</svg>\n");
}

}  // namespace tide::surface
