#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tide/core/memory_usage.hpp"
#include "tide/core/types.hpp"

namespace tide {

/// What a field holds: one real number, D real components, or one integer index per particle.
enum class FieldKind { scalar, vector, index };

/// Typed handles to fields. A pass resolves its handles once when the pipeline is built, so hot
/// loops never look a field up by name. A handle names its slot and the set that made it (and
/// that set's copies); a default-constructed handle names none. Reading a set through a handle
/// of another set, or a default one, throws std::logic_error (a check per pass, not per
/// particle). A field a scene may lack is a std::optional handle; reading an absent one throws.
struct ScalarField {
  std::size_t slot = 0;
  std::uint32_t set = 0;  // the owning set's tag; 0: no set
};
struct VectorField {
  std::size_t slot = 0;
  std::uint32_t set = 0;
};
struct IndexField {
  std::size_t slot = 0;
  std::uint32_t set = 0;
};

/// Read-write view of a vector field: D pointers, one per component array.
template <int D>
struct VectorView {
  std::array<Real*, D> component{};

  Vector<D> operator[](std::size_t i) const {
    Vector<D> v;
    for (int d = 0; d < D; ++d) v[d] = component[d][i];
    return v;
  }
  void set(std::size_t i, const Vector<D>& v) const {
    for (int d = 0; d < D; ++d) component[d][i] = v[d];
  }
};

/// Read-only view of a vector field.
template <int D>
struct ConstVectorView {
  std::array<const Real*, D> component{};

  ConstVectorView() = default;
  ConstVectorView(const VectorView<D>& view) {  // NOLINT(google-explicit-constructor)
    for (int d = 0; d < D; ++d) component[d] = view.component[d];
  }
  Vector<D> operator[](std::size_t i) const {
    Vector<D> v;
    for (int d = 0; d < D; ++d) v[d] = component[d][i];
    return v;
  }
};

/// Name, kind and number of component arrays of a field.
struct FieldInfo {
  std::string name;
  FieldKind kind = FieldKind::scalar;
  int components = 1;
  std::size_t slot = 0;
};

/// Particles in structure-of-arrays layout: every field is one flat array per component
/// (x[0][i], x[1][i], ...), created on demand and reordered together.
///
/// Every set has two fields from the start: "id" (a unique, persistent particle number) and
/// "position". Other fields exist only once a pipeline asks for them.
template <int D>
class ParticleSet {
 public:
  static_assert(D == 2 || D == 3, "TideSPH supports two and three dimensions");
  static constexpr int dimension = D;

  ParticleSet();

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  /// Appends `count` particles with fresh ids and all other fields zero; returns the index of
  /// the first new particle.
  std::size_t append(std::size_t count);

  /// The id the next appended particle takes.
  Index next_id() const { return next_id_; }
  /// Makes the set `count` particles long (fields cut, or grown with zeros) with `next_id` the
  /// next fresh id: what a checkpoint's restore does before it sets every field.
  void resize(std::size_t count, Index next_id);

  /// Creates the field if it does not exist yet and returns its handle. Asking for an existing
  /// name with another kind is an error (std::invalid_argument).
  ScalarField add_scalar(std::string_view name);
  VectorField add_vector(std::string_view name);
  IndexField add_index(std::string_view name);

  /// Handles of existing fields; std::out_of_range names the missing field.
  ScalarField scalar(std::string_view name) const;
  VectorField vector(std::string_view name) const;
  IndexField index(std::string_view name) const;
  bool has(std::string_view name) const;

  VectorField position() const { return position_; }
  IndexField id() const { return id_; }

  std::span<Real> operator[](ScalarField field) { return {reals_[checked(field)].data(), size_}; }
  std::span<const Real> operator[](ScalarField field) const { return {reals_[checked(field)].data(), size_}; }
  std::span<Index> operator[](IndexField field) { return {indices_[checked(field)].data(), size_}; }
  std::span<const Index> operator[](IndexField field) const { return {indices_[checked(field)].data(), size_}; }
  VectorView<D> operator[](VectorField field);
  ConstVectorView<D> operator[](VectorField field) const;
  /// An optional field (one a scene may lack); std::logic_error when it is absent.
  template <class Handle>
  auto operator[](const std::optional<Handle>& field) {
    return (*this)[present(field)];
  }
  template <class Handle>
  auto operator[](const std::optional<Handle>& field) const {
    return (*this)[present(field)];
  }

  /// Reorders every field by one gather: new[i] = old[order[i]]. `order` may be shorter than
  /// size(); the particles it does not name are removed. Entries must be distinct. Each field is
  /// gathered into `scratch` and copied back, one field at a time, so the caller lends the
  /// workspace (permute_scratch_bytes(order.size()), aligned for Real) and the set keeps none.
  void permute(std::span<const Index> order, std::span<std::byte> scratch);

  /// Bytes of scratch `permute` needs to reorder into `count` particles: one array of the widest element type.
  static constexpr std::size_t permute_scratch_bytes(std::size_t count) {
    return count * (sizeof(Real) > sizeof(Index) ? sizeof(Real) : sizeof(Index));
  }

  /// Fields in creation order.
  const std::vector<FieldInfo>& fields() const { return fields_; }

  /// Bytes the field arrays hold (all fields, all components): their capacity, which can exceed
  /// size() after appends or removals.
  std::size_t field_bytes() const;

  /// Adds one item per field ("<owner>.<field>").
  void add_memory(MemoryUsage& usage, const std::string& owner) const;

 private:
  template <class Handle>
  std::size_t checked(const Handle& field) const {
    if (field.set != tag_) throw_foreign_handle(field.set);
    return field.slot;
  }
  template <class Handle>
  static const Handle& present(const std::optional<Handle>& field) {
    if (!field) throw_absent_field();
    return *field;
  }
  [[noreturn]] static void throw_foreign_handle(std::uint32_t set);
  [[noreturn]] static void throw_absent_field();
  const FieldInfo* find(std::string_view name) const;
  const FieldInfo& require(std::string_view name, FieldKind kind) const;
  std::size_t add(std::string_view name, FieldKind kind);

  std::uint32_t tag_;  // a number of its own, shared with its copies: what its handles carry
  std::size_t size_ = 0;
  Index next_id_ = 0;
  std::vector<FieldInfo> fields_;
  std::vector<std::vector<Real>> reals_;
  std::vector<std::vector<Index>> indices_;
  VectorField position_;
  IndexField id_;
};

extern template class ParticleSet<2>;
extern template class ParticleSet<3>;

}  // namespace tide
