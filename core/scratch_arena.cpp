#include "tide/core/scratch_arena.hpp"

#include <stdexcept>

namespace tide {

void ScratchArena::reset(std::size_t bytes) {
  used_ = 0;
  if (bytes <= capacity_) return;
  release();
  // A little headroom, so that a phase growing by a few particles per step does not reallocate
  // every step.
  const std::size_t capacity = aligned(bytes + bytes / 32);
  storage_.reset(static_cast<std::byte*>(::operator new (capacity, std::align_val_t{alignment})));
  capacity_ = capacity;
}

std::span<std::byte> ScratchArena::take_bytes(std::size_t bytes) {
  const std::size_t size = aligned(bytes);
  if (size > capacity_ - used_) throw std::length_error("scratch arena: a phase took more than it reserved");
  std::span<std::byte> span(storage_.get() + used_, bytes);
  used_ += size;
  return span;
}

void ScratchArena::release() {
  storage_.reset();
  capacity_ = 0;
  used_ = 0;
}

}  // namespace tide
