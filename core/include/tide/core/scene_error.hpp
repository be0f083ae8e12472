#pragma once

// The error of a scene that cannot be simulated, shared by the scene reader (io/), which refuses
// what a scene file says wrongly, and the solvers' capability check (solvers/capabilities.hpp),
// which refuses combinations no scheme supports. Both name the file and the JSON key path.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace tide::scene {

/// A scene that cannot be simulated. what() reads
///   dam.json: /solver/cfl: expected a number > 0, got "fast"
/// or, for text that is not JSON,
///   dam.json: line 4, column 12: expected valid JSON, got syntax error while parsing ...
/// A std::invalid_argument: code that builds a solver from a scene catches bad scenes as such.
class SceneError : public std::invalid_argument {
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

}  // namespace tide::scene
