#include "vtk_file.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "xml_text.hpp"

namespace tide::io {
namespace {

// The VTK XML formats: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
// ("XML File Formats"). With encoding "raw", each array's bytes follow one 64-bit length
// (header_type UInt64), and an array's offset counts from the byte after the '_' that opens the
// appended data.
constexpr const char* byte_order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

template <class T>
constexpr const char* vtk_type() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  if constexpr (std::is_same_v<T, float>) return "Float32";
  if constexpr (std::is_same_v<T, std::uint32_t>) return "UInt32";
  if constexpr (std::is_same_v<T, std::uint64_t>) return "UInt64";
  if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
}

/// One array of the file: its XML attributes and how to write its bytes.
struct AppendedArray {
  std::string name;
  const char* type;
  int components;
  std::uint64_t bytes;
  std::function<void(std::ostream&)> write;
};

template <class T>
void write_values(std::ostream& out, const T* values, std::size_t count) {
  out.write(reinterpret_cast<const char*>(values), static_cast<std::streamsize>(count * sizeof(T)));
}

/// `count` tuples of `width` components, component c from columns[c] (absent columns zero), in
/// blocks through a small buffer.
template <class T, std::size_t C>
void write_interleaved(std::ostream& out, const std::array<const T*, C>& columns, std::size_t width,
                       std::size_t count) {
  constexpr std::size_t block = 4096;
  std::vector<T> buffer(block * width);
  for (std::size_t first = 0; first < count; first += block) {
    const std::size_t rows = std::min(block, count - first);
    for (std::size_t i = 0; i < rows; ++i)
      for (std::size_t c = 0; c < width; ++c) buffer[i * width + c] = c < C ? columns[c][first + i] : T(0);
    write_values(out, buffer.data(), rows * width);
  }
}

template <class T>
AppendedArray contiguous_array(std::string name, const T* values, std::size_t count) {
  return {std::move(name), vtk_type<T>(), 1, count * sizeof(T),
          [values, count](std::ostream& out) { write_values(out, values, count); }};
}

template <int D>
AppendedArray vector_array(std::string name, const ConstVectorView<D>& view, std::size_t width, std::size_t count) {
  return {std::move(name), vtk_type<Real>(), static_cast<int>(width), count * width * sizeof(Real),
          [view, width, count](std::ostream& out) { write_interleaved(out, view.component, width, count); }};
}

/// A counting sequence start, start + 1, ..., start + count - 1, written without storing it.
AppendedArray counting_array(std::string name, std::uint32_t start, std::size_t count) {
  return {std::move(name), vtk_type<std::uint32_t>(), 1, count * sizeof(std::uint32_t),
          [start, count](std::ostream& out) {
            constexpr std::size_t block = 4096;
            std::array<std::uint32_t, block> buffer{};
            for (std::size_t first = 0; first < count; first += block) {
              const std::size_t rows = std::min(block, count - first);
              for (std::size_t i = 0; i < rows; ++i) buffer[i] = static_cast<std::uint32_t>(start + first + i);
              write_values(out, buffer.data(), rows);
            }
          }};
}

/// VTK_VERTEX (1) for every cell.
AppendedArray vertex_types(std::size_t count) {
  return {"types", vtk_type<std::uint8_t>(), 1, count, [count](std::ostream& out) {
            const std::vector<std::uint8_t> types(count, 1);
            write_values(out, types.data(), count);
          }};
}

/// The <DataArray> elements of `arrays`, their offsets counted on from `offset`.
std::string data_array_elements(const std::vector<AppendedArray>& arrays, std::uint64_t& offset,
                                const std::string& indent, const char* tuples_attribute = nullptr) {
  std::string text;
  for (const AppendedArray& array : arrays) {
    text += indent + "<DataArray type=\"" + array.type + "\" Name=\"" + xml_escaped(array.name) + "\"";
    if (array.components > 1) text += " NumberOfComponents=\"" + std::to_string(array.components) + "\"";
    if (tuples_attribute != nullptr) text += std::string(" ") + tuples_attribute + "=\"1\"";
    text += " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    offset += sizeof(std::uint64_t) + array.bytes;
  }
  return text;
}

}  // namespace

template <int D>
void write_vtu_file(const std::filesystem::path& path, const ParticleSet<D>& set, const std::vector<FieldInfo>& fields,
                    double time, std::uint64_t step) {
  const std::size_t count = set.size();
  const std::vector<AppendedArray> field_data{contiguous_array("TimeValue", &time, 1),
                                              contiguous_array("step", &step, 1)};
  std::vector<AppendedArray> point_data;
  for (const FieldInfo& field : fields) {
    if (field.name == "position") continue;
    switch (field.kind) {
      case FieldKind::scalar:
        point_data.push_back(contiguous_array(field.name, set[set.scalar(field.name)].data(), count));
        break;
      case FieldKind::index:
        point_data.push_back(contiguous_array(field.name, set[set.index(field.name)].data(), count));
        break;
      case FieldKind::vector:
        point_data.push_back(vector_array<D>(field.name, set[set.vector(field.name)], D, count));
        break;
    }
  }
  // VTK's points have three coordinates.
  const std::vector<AppendedArray> points{vector_array<D>("position", set[set.position()], 3, count)};
  const std::vector<AppendedArray> cells{counting_array("connectivity", 0, count), counting_array("offsets", 1, count),
                                         vertex_types(count)};

  std::uint64_t offset = 0;
  const std::string points_count = std::to_string(count);
  std::string header = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" ") +
                       "byte_order=\"" + byte_order + "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
  header +=
      "    <FieldData>\n" + data_array_elements(field_data, offset, "      ", "NumberOfTuples") + "    </FieldData>\n";
  header += "    <Piece NumberOfPoints=\"" + points_count + "\" NumberOfCells=\"" + points_count + "\">\n";
  header += "      <PointData>\n" + data_array_elements(point_data, offset, "        ") + "      </PointData>\n";
  header += "      <Points>\n" + data_array_elements(points, offset, "        ") + "      </Points>\n";
  header += "      <Cells>\n" + data_array_elements(cells, offset, "        ") + "      </Cells>\n";
  header += "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";

  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << header;
  for (const std::vector<AppendedArray>* section : {&field_data, &std::as_const(point_data), &points, &cells}) {
    for (const AppendedArray& array : *section) {
      write_values(out, &array.bytes, 1);
      array.write(out);
    }
  }
  out << "\n  </AppendedData>\n</VTKFile>\n";
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write the VTK file");
}

std::string pvd_document(const std::vector<CollectionEntry>& entries) {
  std::string document = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" ") +
                         "byte_order=\"" + byte_order + "\">\n  <Collection>\n";
  for (const CollectionEntry& entry : entries)
    document += "    <DataSet timestep=\"" + exact_text(entry.time) + "\" part=\"0\" file=\"" +
                xml_escaped(entry.file) + "\"/>\n";
  return document + "  </Collection>\n</VTKFile>\n";
}

template void write_vtu_file<2>(const std::filesystem::path&, const ParticleSet<2>&, const std::vector<FieldInfo>&,
                                double, std::uint64_t);
template void write_vtu_file<3>(const std::filesystem::path&, const ParticleSet<3>&, const std::vector<FieldInfo>&,
                                double, std::uint64_t);

}  // namespace tide::io
