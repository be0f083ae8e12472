// PLY (Turk, "The PLY Polygon File Format", 1994), ascii and binary_little_endian, read by TideSPH
// itself: Debian has no maintained PLY library. The vertex element's x, y, z and the face
// element's vertex_indices (or vertex_index) list are read; other properties and elements are
// skipped by their declared types.
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_file.hpp"

namespace tide::io {
namespace {

static_assert(std::endian::native == std::endian::little, "the binary PLY reader assumes a little-endian machine");

enum class Type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<Type> type_named(std::string_view name) {
  if (name == "char" || name == "int8") return Type::int8;
  if (name == "uchar" || name == "uint8") return Type::uint8;
  if (name == "short" || name == "int16") return Type::int16;
  if (name == "ushort" || name == "uint16") return Type::uint16;
  if (name == "int" || name == "int32") return Type::int32;
  if (name == "uint" || name == "uint32") return Type::uint32;
  if (name == "float" || name == "float32") return Type::float32;
  if (name == "double" || name == "float64") return Type::float64;
  return std::nullopt;
}

std::size_t size_of(Type type) {
  switch (type) {
    case Type::int8:
    case Type::uint8:
      return 1;
    case Type::int16:
    case Type::uint16:
      return 2;
    case Type::int32:
    case Type::uint32:
    case Type::float32:
      return 4;
    case Type::float64:
      return 8;
  }
  return 8;
}

struct Property {
  std::string name;
  Type type = Type::float64;
  std::optional<Type> count_type;  // set for a list property
};

struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;

  // The fewest bytes one instance takes: binary, its scalars and list counts; ascii, one digit and
  // one separator per value.
  std::size_t least_bytes(bool binary) const {
    std::size_t bytes = 0;
    for (const Property& property : properties)
      bytes += binary ? size_of(property.count_type.value_or(property.type)) : 2;
    return bytes;
  }
};

struct Header {
  bool binary = false;
  std::vector<Element> elements;
  std::size_t body = 0;  // offset of the first byte after end_header
};

Header read_header(const std::filesystem::path& file, const std::string& bytes) {
  const std::size_t end = bytes.find("end_header");
  if (!bytes.starts_with("ply") || end == std::string::npos)
    refuse_mesh(file, "a PLY file (\"ply\" first, then a header up to \"end_header\")", "no such header");
  Header header;
  header.body = bytes.find('\n', end);
  header.body = header.body == std::string::npos ? bytes.size() : header.body + 1;
  std::istringstream lines(bytes.substr(0, end));
  std::string line;
  bool format_given = false;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string format;
      words >> format;
      if (format != "ascii" && format != "binary_little_endian")
        refuse_mesh(file, "PLY format ascii or binary_little_endian", quoted_text(format));
      header.binary = format == "binary_little_endian";
      format_given = true;
    } else if (keyword == "element") {
      Element element;
      long long count = -1;
      words >> element.name >> count;
      if (!words || count < 0) refuse_mesh(file, "\"element NAME COUNT\" with a count >= 0", quoted_text(line));
      element.count = static_cast<std::size_t>(count);
      header.elements.push_back(element);
    } else if (keyword == "property") {
      if (header.elements.empty()) refuse_mesh(file, "a PLY property after its element", quoted_text(line));
      Property property;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string count_type;
        words >> count_type >> type;
        property.count_type = type_named(count_type);
        if (!property.count_type) refuse_mesh(file, "a PLY list count type", quoted_text(line));
      }
      const std::optional<Type> value_type = type_named(type);
      words >> property.name;
      if (!value_type || !words) refuse_mesh(file, "\"property TYPE NAME\" of a PLY type", quoted_text(line));
      property.type = *value_type;
      header.elements.back().properties.push_back(property);
    }
  }
  if (!format_given) refuse_mesh(file, "a PLY format line", "none");
  return header;
}

// The body's values one by one: words of text (ascii) or little-endian bytes.
class Values {
 public:
  Values(const std::filesystem::path& file, std::string_view body, bool binary)
      : file_(file), body_(body), binary_(binary) {}

  double next(Type type) { return binary_ ? next_binary(type) : next_word(); }

  std::size_t left() const { return body_.size() - position_; }

 private:
  double next_word() {
    while (position_ < body_.size() && std::isspace(static_cast<unsigned char>(body_[position_]))) ++position_;
    const std::size_t start = position_;
    while (position_ < body_.size() && !std::isspace(static_cast<unsigned char>(body_[position_]))) ++position_;
    if (start == position_) truncated();
    double value = 0;
    const char* first = body_.data() + start;
    if (*first == '+') ++first;
    const auto [end, error] = std::from_chars(first, body_.data() + position_, value);
    if (error != std::errc{} || end != body_.data() + position_)
      refuse_mesh(file_, "a number (PLY ascii)", quoted_text(body_.substr(start, position_ - start)));
    return value;
  }

  template <class T>
  double take() {
    T value;
    if (left() < sizeof value) truncated();
    std::memcpy(&value, body_.data() + position_, sizeof value);
    position_ += sizeof value;
    return static_cast<double>(value);
  }

  double next_binary(Type type) {
    switch (type) {
      case Type::int8:
        return take<std::int8_t>();
      case Type::uint8:
        return take<std::uint8_t>();
      case Type::int16:
        return take<std::int16_t>();
      case Type::uint16:
        return take<std::uint16_t>();
      case Type::int32:
        return take<std::int32_t>();
      case Type::uint32:
        return take<std::uint32_t>();
      case Type::float32:
        return take<float>();
      case Type::float64:
        return take<double>();
    }
    return take<double>();
  }

  [[noreturn]] void truncated() const {
    refuse_mesh(file_, "as many values as the PLY header declares", "a file that ends early (truncated)");
  }

  const std::filesystem::path& file_;
  std::string_view body_;
  bool binary_;
  std::size_t position_ = 0;
};

// A vertex index as read: a whole number in [0, 2^32).
std::uint32_t vertex_index(const std::filesystem::path& file, double value, std::size_t face) {
  if (!(value >= 0 && value < 4294967296.0 && value == static_cast<double>(static_cast<std::uint64_t>(value))))
    refuse_mesh(file, "face vertex indices that are whole numbers >= 0",
                "face " + std::to_string(face) + " with the index " + std::to_string(value));
  return static_cast<std::uint32_t>(value);
}

}  // namespace

scene::TriangleMesh read_ply(const std::filesystem::path& file) {
  const std::string bytes = read_file_bytes(file);
  const Header header = read_header(file, bytes);
  Values values(file, std::string_view(bytes).substr(header.body), header.binary);
  scene::TriangleMesh mesh;
  std::vector<std::uint32_t> corners;
  for (const Element& element : header.elements) {
    const std::size_t least = element.least_bytes(header.binary);
    if (least > 0 && element.count > values.left() / least) {
      refuse_mesh(file, "a PLY element count the file can hold",
                  std::to_string(element.count) + " " + element.name + " elements of at least " +
                      std::to_string(least) + " bytes in " + std::to_string(values.left()) + " bytes");
    }
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    if (is_vertex) mesh.vertices.reserve(element.count);
    for (std::size_t k = 0; k < element.count; ++k) {
      std::array<double, 3> xyz{};
      for (const Property& property : element.properties) {
        if (property.count_type) {
          const double count = values.next(*property.count_type);
          const bool indices = is_face && (property.name == "vertex_indices" || property.name == "vertex_index");
          corners.clear();
          for (double c = 0; c < count; ++c) {
            const double value = values.next(property.type);
            if (indices) corners.push_back(vertex_index(file, value, k));
          }
          if (indices) add_polygon(mesh, corners);
          continue;
        }
        const double value = values.next(property.type);
        if (is_vertex && property.name.size() == 1 && property.name[0] >= 'x' && property.name[0] <= 'z')
          xyz[static_cast<std::size_t>(property.name[0] - 'x')] = value;
      }
      if (is_vertex) mesh.vertices.push_back(xyz);
    }
  }
  return mesh;
}

}  // namespace tide::io
