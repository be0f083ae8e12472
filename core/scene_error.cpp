#include "tide/core/scene_error.hpp"

#include <utility>

namespace tide::scene {

SceneError::SceneError(std::string file, std::string key_path, std::string expected, std::string found)
    : SceneError(file + (key_path.empty() ? "" : ": " + key_path) + ": expected " + expected + ", got " + found, file,
                 key_path, expected, found, 0, 0) {}

SceneError SceneError::syntax(std::string file, std::size_t line, std::size_t column, std::string found) {
  std::string message = file + ": line " + std::to_string(line) + ", column " + std::to_string(column) +
                        ": expected valid JSON, got " + found;
  return SceneError(std::move(message), std::move(file), "", "valid JSON", std::move(found), line, column);
}

SceneError::SceneError(std::string message, std::string file, std::string key_path, std::string expected,
                       std::string found, std::size_t line, std::size_t column)
    : std::invalid_argument(message),
      file_(std::move(file)),
      key_path_(std::move(key_path)),
      expected_(std::move(expected)),
      found_(std::move(found)),
      line_(line),
      column_(column) {}

}  // namespace tide::scene
