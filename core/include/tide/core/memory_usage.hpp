#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tide {

/// Bytes a vector really holds: its capacity, not its size (a vector that shrank keeps what it
/// had, and `v = {}` assigns an empty initializer list, which keeps the capacity too).
template <class T>
std::size_t held_bytes(const std::vector<T>& values) {
  return values.capacity() * sizeof(T);
}

/// Frees what a vector holds. Neither `clear()` nor `v = {}` does: both keep the capacity.
template <class T>
void release_memory(std::vector<T>& values) {
  std::vector<T>().swap(values);
}

/// One buffer (or group of buffers) a structure keeps between steps, and its held bytes.
struct MemoryItem {
  std::string name;
  std::size_t bytes = 0;
};

/// What a simulation keeps in memory, item by item, so that bytes per particle can be itemised
/// and every buffer is seen (the issue-8 accounting). Items are named "<owner>.<buffer>".
class MemoryUsage {
 public:
  void add(std::string name, std::size_t bytes);
  template <class T>
  void add(std::string name, const std::vector<T>& values) {
    add(std::move(name), held_bytes(values));
  }

  const std::vector<MemoryItem>& items() const { return items_; }

  std::size_t total() const;

 private:
  std::vector<MemoryItem> items_;
};

}  // namespace tide
