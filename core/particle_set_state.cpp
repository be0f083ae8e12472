#include "tide/core/particle_set_state.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <vector>

namespace tide {
namespace {

template <class T>
void check_length(std::span<const T> values, std::size_t expected, const std::string& path) {
  if (values.size() != expected)
    throw std::runtime_error("checkpoint entry '" + path + "': expected " + std::to_string(expected) +
                             " values, found " + std::to_string(values.size()));
}

}  // namespace

template <int D>
void save_particles(StateArchive& archive, const std::string& prefix, const ParticleSet<D>& set) {
  const std::size_t n = set.size();
  archive.put_counts(prefix + "/.size", {n, set.next_id()});
  for (const FieldInfo& field : set.fields()) {
    const std::string path = prefix + "/" + field.name;
    if (field.kind == FieldKind::index) {
      const auto values = set[set.index(field.name)];
      archive.put_counts(path, std::vector<std::uint64_t>(values.begin(), values.end()));
    } else if (field.kind == FieldKind::scalar) {
      archive.put_reals(path, set[set.scalar(field.name)]);
    } else {
      const ConstVectorView<D> vectors = set[set.vector(field.name)];
      std::vector<Real> components(D * n);
      for (int d = 0; d < D; ++d) std::copy_n(vectors.component[d], n, components.begin() + d * n);
      archive.put_reals(path, components);
    }
  }
}

template <int D>
void restore_particles(const StateArchive& archive, const std::string& prefix, ParticleSet<D>& set) {
  const std::span<const std::uint64_t> size = archive.counts(prefix + "/.size");
  check_length(size, 2, prefix + "/.size");
  const std::size_t n = size[0];
  set.resize(n, static_cast<Index>(size[1]));
  for (const FieldInfo& field : set.fields()) {
    const std::string path = prefix + "/" + field.name;
    if (field.kind == FieldKind::index) {
      const std::span<const std::uint64_t> values = archive.counts(path);
      check_length(values, n, path);
      std::ranges::transform(values, set[set.index(field.name)].begin(),
                             [](std::uint64_t v) { return static_cast<Index>(v); });
    } else if (field.kind == FieldKind::scalar) {
      const std::span<const Real> values = archive.reals(path);
      check_length(values, n, path);
      std::ranges::copy(values, set[set.scalar(field.name)].begin());
    } else {
      const std::span<const Real> values = archive.reals(path);
      check_length(values, D * n, path);
      const VectorView<D> vectors = set[set.vector(field.name)];
      for (int d = 0; d < D; ++d) std::copy_n(values.begin() + d * n, n, vectors.component[d]);
    }
  }
}

template void save_particles<2>(StateArchive&, const std::string&, const ParticleSet<2>&);
template void save_particles<3>(StateArchive&, const std::string&, const ParticleSet<3>&);
template void restore_particles<2>(const StateArchive&, const std::string&, ParticleSet<2>&);
template void restore_particles<3>(const StateArchive&, const std::string&, ParticleSet<3>&);

}  // namespace tide
