#pragma once

// Scene files (JSON, documented key by key in docs/scenes.md) → the scene model. A scene is
// checked completely before any work starts: every key is known, typed and in range, and the
// geometry leaves the solver something sensible to do. The first problem found is thrown as a
// SceneError that says where it is and what was expected there.

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tide/core/scene.hpp"

namespace tide::io {

/// A scene that cannot be simulated. what() reads
///   dam.json: /solver/cfl: expected a number > 0, got "fast"
/// or, for text that is not JSON,
///   dam.json: line 4, column 12: expected valid JSON, got syntax error while parsing ...
class SceneError : public std::runtime_error {
 public:
  /// A problem at `key_path` (a JSON pointer such as "/fluid/1/box/max/0"; empty for the whole
  /// document). `found` describes what is there, e.g. the offending value as JSON.
  SceneError(std::string file, std::string key_path, std::string expected, std::string found);

  /// Text that does not parse as JSON; line and column count from 1.
  static SceneError syntax(std::string file, std::size_t line, std::size_t column, std::string found);

  const std::string& file() const { return file_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }
  /// Where a syntax error is; 0 for errors that have a key path instead.
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }

 private:
  SceneError(std::string message, std::string file, std::string key_path, std::string expected, std::string found,
             std::size_t line, std::size_t column);

  std::string file_;
  std::string key_path_;
  std::string expected_;
  std::string found_;
  std::size_t line_ = 0;
  std::size_t column_ = 0;
};

/// Reads and checks the scene in `file`; messages name the file as given.
scene::Scene read_scene_file(const std::filesystem::path& file);

/// Checks the scene in `json_text`; `source_name` names it in messages and becomes Scene::source.
/// JSON with // and /* */ comments is accepted.
scene::Scene parse_scene(std::string_view json_text, std::string source_name);

}  // namespace tide::io
