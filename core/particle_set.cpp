#include "tide/core/particle_set.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>
#include <vector>

#include "tide/core/parallel.hpp"
#include "tide/core/scratch_arena.hpp"

namespace tide {
namespace {

const char* kind_name(FieldKind kind) {
  switch (kind) {
    case FieldKind::scalar:
      return "scalar";
    case FieldKind::vector:
      return "vector";
    case FieldKind::index:
      return "index";
  }
  return "unknown";
}

// Gathers into the caller's scratch and copies back, so that the set keeps no second copy of any
// field between reorders; the copy is one more streaming pass per field.
template <class T>
void gather(std::vector<T>& values, std::span<std::byte> scratch_bytes, std::span<const Index> order) {
  const std::span<T> scratch = objects_in<T>(scratch_bytes, order.size());
  for_each_particle(order.size(), [&](std::size_t i) { scratch[i] = values[order[i]]; });
  values.resize(order.size());
  for_each_particle(order.size(), [&](std::size_t i) { values[i] = scratch[i]; });
}

// Every set made (not copied) takes the next tag; 0 is no set's.
std::atomic<std::uint32_t> next_set_tag{1};

}  // namespace

template <int D>
ParticleSet<D>::ParticleSet() : tag_(next_set_tag.fetch_add(1, std::memory_order_relaxed)) {
  id_ = add_index("id");
  position_ = add_vector("position");
}

template <int D>
void ParticleSet<D>::throw_foreign_handle(std::uint32_t set) {
  throw std::logic_error(set == 0 ? "a default-constructed field handle names no field"
                                  : "a field handle used on a particle set other than the one that made it");
}

template <int D>
void ParticleSet<D>::throw_absent_field() {
  throw std::logic_error("an optional field this particle set does not have was read");
}

template <int D>
std::size_t ParticleSet<D>::append(std::size_t count) {
  if (count > std::numeric_limits<Index>::max() - size_)
    throw std::length_error("a particle set holds at most 2^32 - 1 particles");
  const std::size_t first = size_;
  size_ += count;
  for (auto& values : reals_) values.resize(size_, Real(0));
  for (auto& values : indices_) values.resize(size_, Index(0));
  auto ids = (*this)[id_];
  for (std::size_t i = first; i < size_; ++i) ids[i] = next_id_++;
  return first;
}

template <int D>
void ParticleSet<D>::resize(std::size_t count, Index next_id) {
  if (count > std::numeric_limits<Index>::max())
    throw std::length_error("a particle set holds at most 2^32 - 1 particles");
  size_ = count;
  next_id_ = next_id;
  for (auto& values : reals_) values.resize(size_, Real(0));
  for (auto& values : indices_) values.resize(size_, Index(0));
}

template <int D>
const FieldInfo* ParticleSet<D>::find(std::string_view name) const {
  const auto it = std::find_if(fields_.begin(), fields_.end(), [&](const FieldInfo& f) { return f.name == name; });
  return it == fields_.end() ? nullptr : &*it;
}

template <int D>
bool ParticleSet<D>::has(std::string_view name) const {
  return find(name) != nullptr;
}

template <int D>
const FieldInfo& ParticleSet<D>::require(std::string_view name, FieldKind kind) const {
  const FieldInfo* field = find(name);
  if (field == nullptr) throw std::out_of_range("particle set has no field '" + std::string(name) + "'");
  if (field->kind != kind)
    throw std::invalid_argument("field '" + std::string(name) + "' is a " + kind_name(field->kind) + " field, not a " +
                                kind_name(kind) + " field");
  return *field;
}

template <int D>
std::size_t ParticleSet<D>::add(std::string_view name, FieldKind kind) {
  if (const FieldInfo* existing = find(name)) return require(name, kind).slot;
  if (name.empty()) throw std::invalid_argument("a field needs a name");
  FieldInfo info{std::string(name), kind, kind == FieldKind::vector ? D : 1, 0};
  if (kind == FieldKind::index) {
    info.slot = indices_.size();
    indices_.emplace_back(size_, Index(0));
  } else {
    info.slot = reals_.size();
    for (int c = 0; c < info.components; ++c) reals_.emplace_back(size_, Real(0));
  }
  fields_.push_back(info);
  return info.slot;
}

template <int D>
ScalarField ParticleSet<D>::add_scalar(std::string_view name) {
  return {add(name, FieldKind::scalar), tag_};
}
template <int D>
VectorField ParticleSet<D>::add_vector(std::string_view name) {
  return {add(name, FieldKind::vector), tag_};
}
template <int D>
IndexField ParticleSet<D>::add_index(std::string_view name) {
  return {add(name, FieldKind::index), tag_};
}
template <int D>
ScalarField ParticleSet<D>::scalar(std::string_view name) const {
  return {require(name, FieldKind::scalar).slot, tag_};
}
template <int D>
VectorField ParticleSet<D>::vector(std::string_view name) const {
  return {require(name, FieldKind::vector).slot, tag_};
}
template <int D>
IndexField ParticleSet<D>::index(std::string_view name) const {
  return {require(name, FieldKind::index).slot, tag_};
}

template <int D>
VectorView<D> ParticleSet<D>::operator[](VectorField field) {
  const std::size_t slot = checked(field);
  VectorView<D> view;
  for (int d = 0; d < D; ++d) view.component[d] = reals_[slot + d].data();
  return view;
}

template <int D>
ConstVectorView<D> ParticleSet<D>::operator[](VectorField field) const {
  const std::size_t slot = checked(field);
  ConstVectorView<D> view;
  for (int d = 0; d < D; ++d) view.component[d] = reals_[slot + d].data();
  return view;
}

template <int D>
void ParticleSet<D>::permute(std::span<const Index> order, std::span<std::byte> scratch) {
  if (order.size() > size_) throw std::invalid_argument("permutation is longer than the particle set");
  if (scratch.size() < permute_scratch_bytes(order.size()))
    throw std::invalid_argument("permutation scratch is smaller than one field");
  for (auto& values : reals_) gather(values, scratch, order);
  for (auto& values : indices_) gather(values, scratch, order);
  size_ = order.size();
}

template <int D>
std::size_t ParticleSet<D>::field_bytes() const {
  std::size_t bytes = 0;
  for (const auto& values : reals_) bytes += held_bytes(values);
  for (const auto& values : indices_) bytes += held_bytes(values);
  return bytes;
}

template <int D>
void ParticleSet<D>::add_memory(MemoryUsage& usage, const std::string& owner) const {
  for (const FieldInfo& field : fields_) {
    std::size_t bytes = 0;
    if (field.kind == FieldKind::index) {
      bytes = held_bytes(indices_[field.slot]);
    } else {
      for (int c = 0; c < field.components; ++c) bytes += held_bytes(reals_[field.slot + std::size_t(c)]);
    }
    usage.add(owner + "." + field.name, bytes);
  }
}

template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace tide
