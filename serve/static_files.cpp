#include "tide/serve/static_files.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace tide::serve {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 6> content_types{{
    {".html", "text/html; charset=utf-8"},
    {".js", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},
    {".png", "image/png"},
    {".svg", "image/svg+xml"},
    {".ico", "image/x-icon"},
}};

bool allowed_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
         c == '-' || c == '/';
}

bool safe_segments(std::string_view path) {
  std::size_t start = 1;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string_view segment = path.substr(start, end - start);
    if (segment == "." || segment == "..") return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

std::optional<StaticFile> find_static_file(const std::filesystem::path& root, std::string_view request_path) {
  if (request_path.empty() || request_path.front() != '/') return std::nullopt;
  if (!std::all_of(request_path.begin(), request_path.end(), allowed_character)) return std::nullopt;
  if (!safe_segments(request_path)) return std::nullopt;
  const std::string relative = request_path == "/" ? "index.html" : std::string(request_path.substr(1));
  std::error_code error;
  const std::filesystem::path base = std::filesystem::canonical(root, error);
  if (error) return std::nullopt;
  const std::filesystem::path file = std::filesystem::canonical(base / relative, error);
  if (error || !std::filesystem::is_regular_file(file, error)) return std::nullopt;
  // Inside the root once links are followed: the root's path is a prefix of the file's.
  if (std::mismatch(base.begin(), base.end(), file.begin(), file.end()).first != base.end()) return std::nullopt;
  const std::string extension = file.extension().string();
  for (const auto& [ending, type] : content_types)
    if (extension == ending) return StaticFile{file, std::string(type)};
  return std::nullopt;
}

}  // namespace tide::serve
