#include "tide/io/frame_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "hdf5_calls.hpp"
#include "tide/io/atomic_file.hpp"
#include "vtk_file.hpp"
#include "xml_text.hpp"

namespace tide::io {
namespace {

/// Scalar and index fields are stored as they are, (N); a vector field's D component arrays are
/// interleaved into one (N, D) dataset, the layout ParaView and numpy expect of a vector.
template <int D>
void write_field(const CheckedCalls& h5, hid_t group, const ParticleSet<D>& set, const FieldInfo& field,
                 std::vector<Real>& interleaved) {
  const std::size_t count = set.size();
  switch (field.kind) {
    case FieldKind::scalar: {
      const hsize_t shape[] = {count};
      write_dataset(h5, group, field.name, shape, real_file_type(), real_memory_type(),
                    set[set.scalar(field.name)].data());
      return;
    }
    case FieldKind::index: {
      const hsize_t shape[] = {count};
      write_dataset(h5, group, field.name, shape, H5T_STD_U32LE, H5T_NATIVE_UINT32, set[set.index(field.name)].data());
      return;
    }
    case FieldKind::vector: {
      const ConstVectorView<D> vectors = set[set.vector(field.name)];
      interleaved.resize(count * D);
      for (std::size_t i = 0; i < count; ++i)
        for (int d = 0; d < D; ++d) interleaved[i * D + d] = vectors.component[d][i];
      const hsize_t shape[] = {count, D};
      write_dataset(h5, group, field.name, shape, real_file_type(), real_memory_type(), interleaved.data());
      return;
    }
  }
}

/// Name of the dataset, beside the frame's group, that holds the particles' vertex cells.
constexpr const char* connectivity_dataset = "xdmf_connectivity";

/// 0, 1, ..., N-1: each particle its own vertex cell. ParaView's Xdmf3 reader builds cells only from
/// explicit connectivity and draws nothing of a grid without cells (the older XDMF 2 reader would
/// generate them). Shuffle + deflate shrink this counting sequence to almost nothing on disk.
void write_connectivity(const CheckedCalls& h5, hid_t file, std::size_t count) {
  std::vector<Index> vertices(count);
  std::iota(vertices.begin(), vertices.end(), Index(0));
  const hsize_t shape[] = {count};
  const Handle properties = h5.own(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "cannot create dataset properties");
  if (count > 0) {  // a chunk may not exceed the extent, so an empty frame stays uncompressed
    const hsize_t chunk[] = {std::min<hsize_t>(count, hsize_t(1) << 16)};
    h5.check(H5Pset_chunk(properties.get(), 1, chunk), "cannot chunk the connectivity");
    h5.check(H5Pset_shuffle(properties.get()), "cannot shuffle the connectivity");
    h5.check(H5Pset_deflate(properties.get(), 1), "cannot compress the connectivity");
  }
  write_dataset(h5, file, connectivity_dataset, shape, H5T_STD_U32LE, H5T_NATIVE_UINT32, vertices.data(),
                properties.get());
}

/// What one frame file holds.
template <int D>
struct FrameContent {
  std::string group_name;
  const ParticleSet<D>& set;
  const std::vector<FieldInfo>& fields;
  double time;
  std::uint64_t step;
  const std::map<std::string, std::string>& attributes;
};

template <int D>
void write_frame_file(const fs::path& path, const FrameContent<D>& frame, std::vector<Real>& interleaved) {
  const QuietHdf5Errors quiet;
  const CheckedCalls h5{path};
  Handle file =
      h5.own(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "cannot create the HDF5 file");
  {
    const Handle group = h5.own(H5Gcreate2(file.get(), frame.group_name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                H5Gclose, "cannot create group '" + frame.group_name + "'");
    write_attribute(h5, group.get(), "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &frame.time);
    write_attribute(h5, group.get(), "step", H5T_STD_U64LE, H5T_NATIVE_UINT64, &frame.step);
    for (const auto& [name, value] : frame.attributes) write_string_attribute(h5, group.get(), name, value);
    for (const FieldInfo& field : frame.fields) write_field(h5, group.get(), frame.set, field, interleaved);
  }
  write_connectivity(h5, file.get(), frame.set.size());
  h5.check(file.close(), "cannot close the HDF5 file (flushing it failed)");
}

// ---------------------------------------------------------------------------------------------
// XDMF 3: one Uniform grid per frame in a Temporal collection, pointing into the frame files.

/// "frames_000012": six digits keep file listings in frame order up to a million frames.
std::string numbered(std::string_view stem, std::size_t index) {
  char digits[24];
  std::snprintf(digits, sizeof digits, "%06zu", index);
  return std::string(stem) + "_" + digits;
}

/// <DataItem> for one dataset of a frame: its shape and the XDMF name of its stored type.
std::string xdmf_data_item(const std::string& file_name, const std::string& group_name, const FieldInfo& field,
                           std::size_t count) {
  std::string dimensions = std::to_string(count);
  if (field.kind == FieldKind::vector) dimensions += " " + std::to_string(field.components);
  const bool is_index = field.kind == FieldKind::index;
  const char* number_type = is_index ? "UInt" : "Float";
  const std::size_t precision = is_index ? sizeof(Index) : sizeof(Real);
  return "<DataItem Dimensions=\"" + dimensions + "\" NumberType=\"" + number_type + "\" Precision=\"" +
         std::to_string(precision) + "\" Format=\"HDF\">" + xml_escaped(file_name) + ":/" + group_name + "/" +
         xml_escaped(field.name) + "</DataItem>";
}

/// XDMF defines "Vector" as three components; "Matrix" is any number of columns. A 2D vector field
/// is therefore a "Matrix" of N rows and 2 columns: ParaView's Xdmf3 and XDMF readers both load it
/// as a 2-component point array (checked with ParaView 5.11), while a 2-column "Vector" breaks the
/// standard (the XDMF 2 reader pads it, other tools may misread it) and a true 3-vector would cost a
/// zero column on disk or a JOIN of hyperslabs in every grid.
const char* xdmf_attribute_type(const FieldInfo& field) {
  if (field.kind != FieldKind::vector) return "Scalar";
  return field.components == 3 ? "Vector" : "Matrix";
}

/// The <Grid> of one frame: every particle a Polyvertex cell of one node, at `position`, carrying
/// the other fields as node attributes.
template <int D>
std::string xdmf_grid(const std::string& file_name, const FrameContent<D>& frame) {
  const std::string count = std::to_string(frame.set.size());
  std::string grid = "      <Grid Name=\"" + frame.group_name + "\" GridType=\"Uniform\">\n";
  grid += "        <Time Value=\"" + exact_text(frame.time) + "\"/>\n";
  grid += "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + count + "\" NodesPerElement=\"1\">\n";
  grid += "          <DataItem Dimensions=\"" + count + "\" NumberType=\"UInt\" Precision=\"4\" Format=\"HDF\">" +
          xml_escaped(file_name) + ":/" + connectivity_dataset + "</DataItem>\n        </Topology>\n";
  for (const FieldInfo& field : frame.fields) {
    const std::string data_item = xdmf_data_item(file_name, frame.group_name, field, frame.set.size());
    if (field.name == "position") {
      grid += std::string("        <Geometry GeometryType=\"") + (D == 2 ? "XY" : "XYZ") + "\">\n          " +
              data_item + "\n        </Geometry>\n";
    } else {
      grid += "        <Attribute Name=\"" + xml_escaped(field.name) + "\" AttributeType=\"" +
              xdmf_attribute_type(field) + "\" Center=\"Node\">\n          " + data_item + "\n        </Attribute>\n";
    }
  }
  return grid + "      </Grid>\n";
}

/// The time of a frame's <Grid> (xdmf_grid wrote it exactly).
double grid_time(const std::string& grid) {
  constexpr std::string_view tag = "<Time Value=\"";
  const std::size_t start = grid.find(tag);
  double time = 0;
  if (start == std::string::npos ||
      std::from_chars(grid.data() + start + tag.size(), grid.data() + grid.size(), time).ec != std::errc())
    throw std::runtime_error("an XDMF grid without a time: " + grid.substr(0, 80));
  return time;
}

/// The .pvd collection of the VTK files of the frames the XDMF grids name.
std::string pvd_of(const std::string& run_name, const std::vector<std::string>& grids) {
  std::vector<CollectionEntry> entries;
  for (std::size_t k = 0; k < grids.size(); ++k)
    entries.push_back({numbered(run_name, k) + ".vtu", grid_time(grids[k])});
  return pvd_document(entries);
}

std::string xdmf_document(const std::string& run_name, const std::vector<std::string>& grids) {
  std::string document = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n";
  document += "    <Grid Name=\"" + xml_escaped(run_name) + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const std::string& grid : grids) document += grid;
  return document + "    </Grid>\n  </Domain>\n</Xdmf>\n";
}

// ---------------------------------------------------------------------------------------------
// Checking what the caller asks for.

/// The field list with "position" in it (ParaView needs the geometry) and each name once.
std::vector<std::string> fields_to_write(std::vector<std::string> fields) {
  if (std::find(fields.begin(), fields.end(), "position") == fields.end()) fields.insert(fields.begin(), "position");
  for (auto it = fields.begin(); it != fields.end(); ++it) {
    if (it->empty() || it->find('/') != std::string::npos)
      throw std::invalid_argument("cannot write field '" + *it + "': a field name is not empty and has no '/'");
    if (std::find(std::next(it), fields.end(), *it) != fields.end())
      throw std::invalid_argument("field '" + *it + "' is listed twice for output");
  }
  return fields;
}

/// The run name becomes a file name and the file part of XDMF's "file:/dataset" references.
void check_run_name(const std::string& run_name) {
  if (run_name.empty() || run_name.find_first_of("/:") != std::string::npos)
    throw std::invalid_argument("run name '" + run_name + "' must be a non-empty file name without '/' or ':'");
}

template <int D>
std::vector<FieldInfo> resolve_fields(const ParticleSet<D>& set, const std::vector<std::string>& names) {
  std::vector<FieldInfo> resolved;
  for (const std::string& name : names) {
    const auto& available = set.fields();
    const auto it =
        std::find_if(available.begin(), available.end(), [&](const FieldInfo& f) { return f.name == name; });
    if (it == available.end()) {
      std::string message = "cannot write field '" + name + "': the particle set has no such field (it has";
      for (const FieldInfo& field : available) message += " " + field.name;
      throw std::invalid_argument(message + ")");
    }
    resolved.push_back(*it);
  }
  return resolved;
}

void check_attribute_names(const std::map<std::string, std::string>& attributes) {
  for (const auto& [name, value] : attributes)
    if (name.empty() || name == "time" || name == "step")
      throw std::invalid_argument("frame attribute name '" + name + "' is empty or taken (time and step are written)");
}

// ---------------------------------------------------------------------------------------------
// Reading a frame file back.

/// "(8, 2)".
std::string shape_text(const std::vector<std::size_t>& shape) {
  std::string text = "(";
  for (std::size_t k = 0; k < shape.size(); ++k) text += (k > 0 ? ", " : "") + std::to_string(shape[k]);
  return text + ")";
}

FrameDataset read_dataset(const CheckedCalls& h5, hid_t group, const std::string& group_path, const std::string& name) {
  const std::string what = "dataset '" + name + "' of " + group_path;
  const Handle dataset = h5.own(H5Oopen(group, name.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + what);
  expect_kind(h5, dataset, H5I_DATASET, what);
  const Handle space = h5.own(H5Dget_space(dataset.get()), H5Sclose, "cannot read the shape of " + what);
  const Handle type = h5.own(H5Dget_type(dataset.get()), H5Tclose, "cannot read the type of " + what);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank != 1 && rank != 2)
    throw_layout_error(h5, what + ": expected shape (N) or (N, D), found " + std::to_string(rank) + " dimensions");
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_FLOAT && type_class != H5T_INTEGER)
    throw_layout_error(h5, what + ": expected numbers (an integer or floating-point type)");

  hsize_t dims[2] = {0, 0};
  h5.check(H5Sget_simple_extent_dims(space.get(), dims, nullptr), "cannot read the shape of " + what);
  FrameDataset result;
  result.shape.assign(dims, dims + rank);
  // A damaged header can claim any shape: refuse one that the stored bytes cannot hold before
  // allocating for it (fields are stored contiguous and uncompressed, so the bytes bound the
  // shape; divisions, so that a huge claimed extent cannot overflow the check).
  const hsize_t value_size = H5Tget_size(type.get());
  const hsize_t stored_values = value_size == 0 ? 0 : H5Dget_storage_size(dataset.get()) / value_size;
  std::size_t value_count = 1;
  for (const std::size_t extent : result.shape) {
    if (extent != 0 && value_count > stored_values / extent)
      throw_layout_error(h5, what + " claims more values than it stores");
    value_count *= extent;
  }
  result.values.resize(value_count);
  h5.check(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, space.get(), space.get(), H5P_DEFAULT, result.values.data()),
           "cannot read " + what);
  return result;
}

/// Particle i is row i of every dataset, and a vector field has as many columns as "position",
/// which is (N, 2) or (N, 3) (docs/output.md).
void check_shapes(const CheckedCalls& h5, const std::string& group_path,
                  const std::map<std::string, FrameDataset>& datasets) {
  const auto position = datasets.find("position");
  if (position == datasets.end())
    throw_layout_error(h5, "expected a dataset 'position' in " + group_path + ", found none");
  const std::vector<std::size_t>& shape = position->second.shape;
  if (shape.size() != 2 || shape[1] < 2 || shape[1] > 3)
    throw_layout_error(
        h5, "dataset 'position' of " + group_path + ": expected shape (N, 2) or (N, 3), found " + shape_text(shape));
  for (const auto& [name, dataset] : datasets) {
    if (dataset.shape[0] != shape[0] || (dataset.shape.size() == 2 && dataset.shape[1] != shape[1]))
      throw_layout_error(h5, "dataset '" + name + "' of " + group_path + ": expected shape " + shape_text({shape[0]}) +
                                 " or " + shape_text(shape) + " (rows and columns as in 'position'), found " +
                                 shape_text(dataset.shape));
  }
}

}  // namespace

Frame read_frame(const fs::path& path) {
  const QuietHdf5Errors quiet;
  const CheckedCalls h5{path};
  const Handle file =
      h5.own(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open as an HDF5 file");
  std::vector<std::string> groups = link_names(h5, file.get(), "the file");
  std::erase(groups, connectivity_dataset);
  if (groups.size() != 1)
    throw_layout_error(h5, "expected one frame group at the root, found " + std::to_string(groups.size()));

  Frame frame;
  frame.group = groups.front();
  const std::string group_path = "/" + frame.group;
  const Handle group =
      h5.own(H5Oopen(file.get(), frame.group.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + group_path);
  expect_kind(h5, group, H5I_GROUP, group_path);
  frame.time = read_number_attribute<double>(h5, group.get(), group_path, "time", H5T_NATIVE_DOUBLE);
  frame.step = read_number_attribute<std::uint64_t>(h5, group.get(), group_path, "step", H5T_NATIVE_UINT64);
  for (const std::string& name : attribute_names(h5, group.get(), group_path))
    if (name != "time" && name != "step")
      frame.attributes[name] = read_string_attribute(h5, group.get(), group_path, name);
  for (const std::string& name : link_names(h5, group.get(), group_path))
    frame.datasets[name] = read_dataset(h5, group.get(), group_path, name);
  check_shapes(h5, group_path, frame.datasets);
  return frame;
}

template <int D>
FrameWriter<D>::FrameWriter(fs::path directory, std::vector<std::string> fields, std::string run_name, VtkFiles vtk)
    : directory_(std::move(directory)),
      fields_(fields_to_write(std::move(fields))),
      run_name_(std::move(run_name)),
      vtk_(vtk) {
  check_run_name(run_name_);
  std::error_code error;
  fs::create_directories(directory_, error);
  if (error) throw std::runtime_error(directory_.string() + ": cannot create the output directory: " + error.message());
}

template <int D>
fs::path FrameWriter<D>::xdmf_path() const {
  return directory_ / (run_name_ + ".xdmf");
}

template <int D>
fs::path FrameWriter<D>::pvd_path() const {
  return directory_ / (run_name_ + ".pvd");
}

template <int D>
void FrameWriter<D>::continue_after(std::vector<std::string> grids) {
  if (vtk_ == VtkFiles::on) pvd_of(run_name_, grids);  // every grid has its time, or nothing changes
  grids_ = std::move(grids);
}

template <int D>
fs::path FrameWriter<D>::write(const ParticleSet<D>& set, double time, std::uint64_t step,
                               const std::map<std::string, std::string>& attributes) {
  const std::vector<FieldInfo> fields = resolve_fields(set, fields_);
  check_attribute_names(attributes);
  const FrameContent<D> frame{numbered("frame", frames_written()), set, fields, time, step, attributes};
  const std::string file_name = numbered(run_name_, frames_written()) + ".h5";
  const fs::path frame_path = directory_ / file_name;

  replace_atomically(frame_path, [&](const fs::path& temporary) { write_frame_file(temporary, frame, interleaved_); });
  if (vtk_ == VtkFiles::on) {
    replace_atomically(directory_ / (numbered(run_name_, frames_written()) + ".vtu"),
                       [&](const fs::path& temporary) { write_vtu_file(temporary, set, fields, time, step); });
  }
  // The XDMF and .pvd files name the new frame only once its files are complete and in place.
  grids_.push_back(xdmf_grid(file_name, frame));
  try {
    replace_text_atomically(xdmf_path(), xdmf_document(run_name_, grids_));
    if (vtk_ == VtkFiles::on) replace_text_atomically(pvd_path(), pvd_of(run_name_, grids_));
  } catch (...) {
    grids_.pop_back();
    throw;
  }
  return frame_path;
}

template class FrameWriter<2>;
template class FrameWriter<3>;

}  // namespace tide::io
