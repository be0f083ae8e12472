#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <span>
#include <type_traits>

namespace tide {

/// Objects of a trivial type T over raw bytes: begins their lifetime (no code runs) so the bytes,
/// whatever they held before, can be used as `count` T. The bytes must be aligned for T and hold
/// at least count × sizeof(T).
template <class T>
std::span<T> objects_in(std::span<std::byte> bytes, std::size_t count) {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);
  T* first = reinterpret_cast<T*>(bytes.data());
  std::uninitialized_default_construct_n(first, count);
  return {std::launder(first), count};
}

/// Memory lent to one phase of a step after another, so that buffers never alive at the same
/// time share their bytes (DualSPHysics borrows its per-step arrays from a pool the same way): the
/// sort and reorder workspace of a neighbour update, then the neighbour list the passes walk. A
/// `reset` ends the previous phase: every span handed out before it is invalid.
class ScratchArena {
 public:
  /// Alignment of every span handed out (a cache line).
  static constexpr std::size_t alignment = 64;

  ScratchArena() = default;
  ScratchArena(ScratchArena&&) noexcept = default;
  ScratchArena& operator=(ScratchArena&&) noexcept = default;

  /// Starts a phase that takes at most `bytes` (counting each span rounded up to `alignment`).
  /// Grows the storage when it is too small (the old storage is freed first: nothing is copied).
  void reset(std::size_t bytes);

  /// The next `count` objects of T of this phase; std::length_error past what reset made room for.
  template <class T>
  std::span<T> take(std::size_t count) {
    return objects_in<T>(take_bytes(count * sizeof(T)), count);
  }

  /// Bytes held (the storage's capacity).
  std::size_t bytes() const { return capacity_; }

  /// Frees the storage.
  void release();

  /// `bytes` rounded up to the alignment: what a span of that many bytes uses of a phase.
  static constexpr std::size_t aligned(std::size_t bytes) { return (bytes + alignment - 1) / alignment * alignment; }

 private:
  struct Free {
    void operator()(std::byte* p) const { ::operator delete (p, std::align_val_t{alignment}); }
  };
  std::span<std::byte> take_bytes(std::size_t bytes);

  std::unique_ptr<std::byte, Free> storage_;
  std::size_t capacity_ = 0;
  std::size_t used_ = 0;
};

}  // namespace tide
