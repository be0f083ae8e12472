#pragma once

// Files that appear complete or not at all: what every writer in io/ uses so that a run killed at
// any moment never leaves a truncated file in place of a good one (DESIGN.md, "Errors and
// stability").

#include <filesystem>
#include <functional>
#include <string>

namespace tide::io {

/// Writes `destination` through `write_to`, which fills a hidden temporary file beside it; the
/// temporary is flushed to disk and renamed over `destination` (atomic on POSIX), or removed on
/// failure, which is rethrown.
void replace_atomically(const std::filesystem::path& destination,
                        const std::function<void(const std::filesystem::path&)>& write_to);

/// Writes `text` to `path` (truncating it); std::runtime_error naming the file on failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// Replaces `path` atomically with `text`, creating its parent folder if needed.
void replace_text_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace tide::io
