#pragma once

// The JSON layer of the scene reader: text → a JSON document, refusing what nlohmann::json would
// accept silently (a key given twice) or could not describe (absurd nesting), and the JSON-pointer
// paths (RFC 6901) that every scene error names.

#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

namespace tide::io {

/// Parses `text` (// and /* */ comments allowed); a SceneError naming `file` for text that is not
/// JSON, a key given twice in an object, or nesting deeper than 64 levels.
nlohmann::json parse_json(std::string_view text, const std::string& file);

/// A key as one JSON pointer token: '~' and '/' are escaped.
std::string pointer_token(std::string_view key);

/// A value as the user wrote it (compact JSON), cut short so that a message stays one line.
std::string describe(const nlohmann::json& value);

/// A JSON value with its JSON pointer from the document root.
struct Node {
  const nlohmann::json* value = nullptr;  // null where the key is absent
  std::string path;

  bool present() const { return value != nullptr; }
};

/// The member `key` of `object`, which must be a checked object.
Node child(const Node& object, std::string_view key);

/// The element `index` of `array`, which must be a checked array.
Node element(const Node& array, std::size_t index);

}  // namespace tide::io
