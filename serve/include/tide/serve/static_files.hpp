#pragma once

// The page's files: what a request path names in the static folder, never a file outside it.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tide::serve {

struct StaticFile {
  std::filesystem::path path;
  std::string content_type;
};

/// The file `request_path` (decoded, as the server received it; "/" names index.html) names in
/// `root`. Empty for a path that is not absolute, has a segment "." or "..", a backslash, a
/// control character or a character outside A-Z a-z 0-9 . _ - /, whose extension is not one the
/// page uses (html, js, css, png, svg, ico), that is not a regular file, or that resolves
/// (symbolic links followed) outside `root`.
std::optional<StaticFile> find_static_file(const std::filesystem::path& root, std::string_view request_path);

}  // namespace tide::serve
