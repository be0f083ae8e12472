#include "tide/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace tide::io {
namespace {

namespace fs = std::filesystem;

/// fsync: without it, a power cut soon after the rename could leave the final name pointing at
/// blocks that were never written, the very truncated file the rename is there to prevent.
void flush_to_disk(const fs::path& path) {
  const int descriptor = ::open(path.c_str(), O_RDONLY);
  if (descriptor < 0) throw std::system_error(errno, std::generic_category(), path.string() + ": cannot open to flush");
  const int status = ::fsync(descriptor);
  const int fsync_errno = errno;
  ::close(descriptor);
  if (status != 0) throw std::system_error(fsync_errno, std::generic_category(), path.string() + ": cannot flush");
}

}  // namespace

void replace_atomically(const fs::path& destination, const std::function<void(const fs::path&)>& write_to) {
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string here.
  std::string hidden_name = ".";
  hidden_name += destination.filename().string();
  hidden_name += ".tmp";
  const fs::path temporary = destination.parent_path() / hidden_name;
  try {
    write_to(temporary);
    flush_to_disk(temporary);
    std::error_code error;
    fs::rename(temporary, destination, error);
    if (error)
      throw std::runtime_error(destination.string() + ": cannot move " + temporary.filename().string() +
                               " into place: " + error.message());
  } catch (...) {
    std::error_code ignored;  // the original failure is the one to report
    fs::remove(temporary, ignored);
    throw;
  }
}

void write_text_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write the file");
}

void replace_text_atomically(const fs::path& path, const std::string& text) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  replace_atomically(path, [&](const fs::path& temporary) { write_text_file(temporary, text); });
}

}  // namespace tide::io
