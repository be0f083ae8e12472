#include "process_memory.hpp"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

#include <fstream>
#include <sstream>
#include <string>

namespace tide::bench {

ResidentMemory resident_memory() {
  ResidentMemory memory;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    std::istringstream fields(line);
    std::string key;
    std::size_t kilobytes = 0;
    fields >> key >> kilobytes;
    if (key == "VmRSS:") memory.current = kilobytes * 1024;
    if (key == "VmHWM:") memory.peak = kilobytes * 1024;
  }
  return memory;
}

HeapMemory heap_memory() {
  HeapMemory memory;
#if defined(__GLIBC__)
  const struct mallinfo2 info = mallinfo2();
  memory.in_use = info.uordblks + info.hblkhd;
  memory.free_kept = info.fordblks;
  memory.mapped = info.hblkhd;
#endif
  return memory;
}

bool reset_peak_resident_memory() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  clear_refs.flush();
  return static_cast<bool>(clear_refs);
}

}  // namespace tide::bench
