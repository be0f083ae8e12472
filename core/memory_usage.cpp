#include "tide/core/memory_usage.hpp"

#include <string>
#include <utility>

namespace tide {

// Out of line: inlined into the passes' memory accounting at -O3, GCC 12 reports a false
// -Warray-bounds on the moved name (its known std::string memcpy diagnostic).
void MemoryUsage::add(std::string name, std::size_t bytes) { items_.push_back({std::move(name), bytes}); }

std::size_t MemoryUsage::total() const {
  std::size_t sum = 0;
  for (const MemoryItem& item : items_) sum += item.bytes;
  return sum;
}

}  // namespace tide
